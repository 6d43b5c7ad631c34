// A furnace test of a .gltf in three.js: the file loaded by three.js's GLTFLoader (as MeshPhysicalMaterial where it
// uses KHR_materials_*), lit by nothing but a uniform white sky of radiance 1 (scene.environment: a constant RGBA
// float equirectangular texture through PMREMGenerator; no lights, no tone mapping), seen by an orthographic camera
// down -z, rendered in headless Chromium (WebGL 2 on SwiftShader) through puppeteer-core. Under such a sky a pixel's
// radiance is the surface's directional albedo toward the camera, so the centre pixel (the sphere's normal toward
// the camera) is three.js's albedo at normal incidence.
// Linear values: the scene is rendered into a float render target (RGBA, FloatType), where three.js applies neither
// tone mapping nor the output colour space (it does so only when it draws to the canvas), and the pixels are read
// back with readRenderTargetPixels. The PNG is the same render drawn to the canvas with outputColorSpace linear and no
// tone mapping: 8-bit linear values, not sRGB-encoded.
//   node gltf_three_furnace.mjs --tools <node_modules with three and puppeteer-core> [--png out.png]
//        [--expect r,g,b --tolerance 0.05] file.gltf
// Prints one JSON line: the centre pixel and the 5 x 5 mean about it (linear RGB), the expected albedo (the file's
// materials[0].extras.gltf_model_albedo_at_normal_incidence, or --expect) and the relative differences, and the same
// off the normal for each angle in extras.gltf_model_albedo_at_degrees (the pixel along the centre row whose normal is
// nearest; the angle of its centre printed). Exits 1 where --tolerance is given and a channel of the centre pixel
// differs by more (relative), 2 on bad use or a failed render.
// Files are served from a server on 127.0.0.1 only; Chromium runs with a new, empty profile and without network
// services.
import { mkdtemp, readFile, rm, writeFile } from 'node:fs/promises';
import { createServer } from 'node:http';
import { createRequire } from 'node:module';
import os from 'node:os';
import path from 'node:path';

const args = process.argv.slice(2);
let tools = process.env.SKINLAYER_GLTF_TOOLS ?? '', png = '', expect = null, tolerance = null, file = '';
for (let k = 0; k < args.length; ++k) {
  if (args[k] === '--tools') tools = args[++k] ?? '';
  else if (args[k] === '--png') png = args[++k] ?? '';
  else if (args[k] === '--expect') expect = (args[++k] ?? '').split(',').map(Number);
  else if (args[k] === '--tolerance') tolerance = Number(args[++k]);
  else file = args[k];
}
if (!tools || !file) {
  console.error('usage: node gltf_three_furnace.mjs --tools <node_modules> [--png out.png] ' +
                '[--expect r,g,b] [--tolerance t] file.gltf');
  process.exit(2);
}
const require = createRequire(import.meta.url);
const puppeteer = require(path.resolve(tools, 'puppeteer-core'));
const gltfText = await readFile(file, 'utf8');
const extras = JSON.parse(gltfText).materials?.[0]?.extras ?? {};
if (!expect) expect = extras.gltf_model_albedo_at_normal_incidence ?? null;
const offNormal = extras.gltf_model_albedo_at_degrees ?? {};  // {"30": [r, g, b], ...}

const kSize = 256;
const page = `<!DOCTYPE html>
<html><head><meta charset="utf-8"><title>skinlayer glTF furnace</title>
<script type="importmap">{"imports": {"three": "/three/build/three.module.js",
                                      "three/addons/": "/three/examples/jsm/"}}</script></head>
<body style="margin:0;background:#000">
<script type="module">
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
const size = ${kSize};
try {
  const renderer = new THREE.WebGLRenderer({ antialias: false, preserveDrawingBuffer: true });
  renderer.setPixelRatio(1);
  renderer.setSize(size, size);
  renderer.toneMapping = THREE.NoToneMapping;
  renderer.outputColorSpace = THREE.LinearSRGBColorSpace;
  document.body.appendChild(renderer.domElement);

  // The white sky: radiance 1 in every direction.
  const width = 64, height = 32, texels = new Float32Array(width * height * 4).fill(1.0);
  const sky = new THREE.DataTexture(texels, width, height, THREE.RGBAFormat, THREE.FloatType);
  sky.mapping = THREE.EquirectangularReflectionMapping;
  sky.colorSpace = THREE.LinearSRGBColorSpace;
  sky.needsUpdate = true;
  const pmrem = new THREE.PMREMGenerator(renderer);
  const scene = new THREE.Scene();
  scene.environment = pmrem.fromEquirectangular(sky).texture;
  scene.background = new THREE.Color(0, 0, 0);

  const gltf = await new GLTFLoader().loadAsync('/model.gltf');
  scene.add(gltf.scene);
  let material = null;
  gltf.scene.traverse((node) => { if (node.isMesh) material = node.material; });

  const camera = new THREE.OrthographicCamera(-1.1, 1.1, 1.1, -1.1, 0.1, 10);
  camera.position.set(0, 0, 3);
  camera.lookAt(0, 0, 0);

  const target = new THREE.WebGLRenderTarget(size, size, { type: THREE.FloatType, format: THREE.RGBAFormat });
  renderer.setRenderTarget(target);
  renderer.render(scene, camera);
  const pixels = new Float32Array(size * size * 4);
  renderer.readRenderTargetPixels(target, 0, 0, size, size, pixels);
  renderer.setRenderTarget(null);
  renderer.render(scene, camera);  // the canvas, for the PNG

  const at = (x, y) => Array.from(pixels.slice(4 * (y * size + x), 4 * (y * size + x) + 3));
  const centre = at(size / 2, size / 2);
  const mean = [0, 0, 0];
  for (let y = size / 2 - 2; y <= size / 2 + 2; ++y) {
    for (let x = size / 2 - 2; x <= size / 2 + 2; ++x) at(x, y).forEach((v, c) => { mean[c] += v / 25; });
  }
  // Off the normal: along the centre row toward +x the sphere's normal makes the angle asin(x) with the view; the
  // pixel whose centre is nearest sin(theta), and the angle its centre has.
  const offNormal = {};
  for (const degrees of ${JSON.stringify(Object.keys(offNormal))}) {
    const x = Math.sin(degrees * Math.PI / 180);
    const column = Math.min(size - 1, Math.round((x + 1.1) / 2.2 * size - 0.5));
    const centreX = ((column + 0.5) / size) * 2.2 - 1.1;
    offNormal[degrees] = { pixel: at(column, size / 2), degrees: Math.asin(Math.min(1, centreX)) * 180 / Math.PI };
  }
  const gl = renderer.getContext();
  const debug = gl.getExtension('WEBGL_debug_renderer_info');
  window.__furnace = {
    centre, mean, corner: at(2, 2), offNormal,
    material: material && {
      type: material.type, color: material.color.toArray(), roughness: material.roughness,
      metalness: material.metalness, ior: material.ior, specularIntensity: material.specularIntensity,
      specularColor: material.specularColor?.toArray(), sheen: material.sheen,
      sheenColor: material.sheenColor?.toArray(), sheenRoughness: material.sheenRoughness,
      clearcoat: material.clearcoat, clearcoatRoughness: material.clearcoatRoughness },
    three: THREE.REVISION,
    gl: debug ? gl.getParameter(debug.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER),
    png: renderer.domElement.toDataURL('image/png'),
  };
} catch (error) {
  window.__furnace = { error: String(error && error.stack || error) };
}
</script></body></html>`;

const types = { '.js': 'text/javascript', '.html': 'text/html', '.gltf': 'model/gltf+json' };
const threeRoot = path.resolve(tools, 'three');
const server = createServer(async (request, response) => {
  try {
    const url = new URL(request.url, 'http://127.0.0.1');
    let body, type;
    if (url.pathname === '/' || url.pathname === '/index.html') [body, type] = [page, types['.html']];
    else if (url.pathname === '/model.gltf') [body, type] = [gltfText, types['.gltf']];
    else if (url.pathname.startsWith('/three/')) {
      const local = path.resolve(threeRoot, '.' + decodeURIComponent(url.pathname.slice('/three'.length)));
      if (!local.startsWith(threeRoot + path.sep)) throw new Error('outside three');
      [body, type] = [await readFile(local), types[path.extname(local)] ?? 'application/octet-stream'];
    } else throw new Error('not served');
    response.writeHead(200, { 'Content-Type': type });
    response.end(body);
  } catch {
    response.writeHead(404);
    response.end();
  }
});
await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
const port = server.address().port;

const profile = await mkdtemp(path.join(os.tmpdir(), 'skinlayer-chromium-'));
let browser = null, result = null;
try {
  browser = await puppeteer.launch({
    executablePath: process.env.SKINLAYER_CHROMIUM ?? '/usr/bin/chromium',
    headless: true,
    userDataDir: profile,
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking',
           '--disable-component-update', '--disable-sync', '--no-first-run', '--use-angle=swiftshader',
           '--enable-unsafe-swiftshader', `--user-data-dir=${profile}`],
  });
  const tab = await browser.newPage();
  const messages = [];
  tab.on('console', (message) => messages.push(`${message.type()}: ${message.text()}`));
  tab.on('pageerror', (error) => messages.push(`pageerror: ${error.message}`));
  await tab.goto(`http://127.0.0.1:${port}/index.html`);
  await tab.waitForFunction('window.__furnace !== undefined', { timeout: 120000 });
  result = await tab.evaluate('window.__furnace');
  if (result.error) {
    console.error(result.error);
    for (const message of messages) console.error(message);
    process.exitCode = 2;
  }
} catch (error) {
  console.error(`furnace: ${error.message}`);
  process.exitCode = 2;
} finally {
  if (browser) await browser.close();
  server.close();
  await rm(profile, { recursive: true, force: true });
}
if (!result || result.error) process.exit(2);

if (png) await writeFile(png, Buffer.from(result.png.split(',')[1], 'base64'));
const relative = expect ? result.centre.map((v, c) => (v - expect[c]) / expect[c]) : null;
const off_normal = Object.fromEntries(Object.entries(result.offNormal).map(([degrees, measured]) => [degrees, {
  pixel_degrees: measured.degrees, three: measured.pixel, expected: offNormal[degrees],
  relative_difference: measured.pixel.map((v, c) => (v - offNormal[degrees][c]) / offNormal[degrees][c]) }]));
console.log(JSON.stringify({ file: path.basename(file), three: result.three, gl: result.gl, centre: result.centre,
                             mean_5x5: result.mean, background: result.corner, expected: expect,
                             relative_difference: relative, off_normal, material: result.material }));
if (tolerance !== null && relative && relative.some((d) => !(Math.abs(d) <= tolerance))) process.exit(1);
