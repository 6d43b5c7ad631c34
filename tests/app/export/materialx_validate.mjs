// `skinlayer export --format mtlx` read by MaterialX itself: the WebAssembly build of MaterialX's core and shader
// generation that the npm package @needle-tools/materialx ships (bin/JsMaterialXGenShader.js with the standard
// libraries packed beside it, MaterialX 1.39.4 in its 1.4.6). For a few presets the exported file must
//   - read, and validate against the standard libraries (Document.validate: every input known to the node
//     definition, of its type, every unit known to its unit type, the material naming its shader);
//   - bind its shader to ND_open_pbr_surface_surfaceshader;
//   - carry subsurface_radius in millimetres (unittype "distance", unit "millimeter"), a unit the standard library
//     defines at 0.001 m;
//   - generate GLSL, and, with the generator's target distance unit set to metres, scale the radius by 0.001 (with
//     the target unit empty, MaterialX's C++ default, the radius enters the shader as written, in the scene's unit).
// And a file broken in each of those ways must fail (the check is not one that passes anything).
//
// With --furnace, MaterialX's own shader is rendered too: the ESSL (WebGL 2) MaterialX generates for the material,
// in headless Chromium through puppeteer-core, under a uniform white environment (radiance and irradiance 1, no
// lights; filtered importance sampling with 1024 samples, the analytic albedo fits, MaterialX's defaults for a
// viewer), one flat pixel seen at 0, 30, 60 and 80 degrees: the directional albedo at the view. At 0 degrees it
// must be the material's own albedo (`skinlayer albedo`, which the fit matches exactly with skinlayer's model of
// the node) within 0.5% per channel. At every angle of the fit's report (0, 20, ..., 80 degrees) it must be the
// albedo skinlayer's OpenPBR model gives the fitted surface (the report's albedo.fitted) within 0.5%; its distance
// from the material is the fit's error.
//
// Usage: node materialx_validate.mjs PACKAGE_DIR SKINLAYER_EXECUTABLE SCRATCH_DIR [--furnace NODE_MODULES CHROMIUM]
//   PACKAGE_DIR: node_modules/@needle-tools/materialx; NODE_MODULES: a node_modules folder holding puppeteer-core;
//   CHROMIUM: the browser's executable. Exit status 0 when every check holds, 1 otherwise, 2 on bad arguments; one
//   line per check on stdout.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import { createRequire } from 'node:module';
import path from 'node:path';

const [packageDir, skinlayer, scratch, furnaceFlag, furnaceModules, chromium] = process.argv.slice(2);
if (!packageDir || !skinlayer || !scratch || (furnaceFlag !== undefined && (furnaceFlag !== '--furnace' || !chromium))) {
  console.error('usage: node materialx_validate.mjs PACKAGE_DIR SKINLAYER_EXECUTABLE SCRATCH_DIR ' +
                '[--furnace NODE_MODULES CHROMIUM]');
  process.exit(2);
}
const bin = path.join(packageDir, 'bin');
const generator = path.join(bin, 'JsMaterialXGenShader.js');
if (!fs.existsSync(generator)) {
  console.error(`materialx_validate: no ${generator} (is ${packageDir} @needle-tools/materialx?)`);
  process.exit(2);
}

// The Emscripten module is written as an ES module for browsers; under Node it wants require and __dirname, so it
// is evaluated as a function of those. Its data package (the libraries) is named .data.txt in the npm package.
async function loadMaterialX() {
  const source = fs.readFileSync(generator, 'utf8').replace(/export\s+default\s+MaterialX\s*;?\s*$/, '');
  const factory = new Function('require', '__dirname', '__filename', `${source}\nreturn MaterialX;`)(
      createRequire(import.meta.url), bin + path.sep, generator);
  return factory({
    locateFile: (file) => path.join(bin, file.endsWith('.data') && !fs.existsSync(path.join(bin, file)) ? `${file}.txt`
                                                                                                          : file),
  });
}

let failures = 0;
function check(condition, what) {
  console.log(`${condition ? 'ok  ' : 'FAIL'} ${what}`);
  if (!condition) failures += 1;
}

const mx = await loadMaterialX();
console.log(`MaterialX ${mx.getVersionString()} (${path.basename(packageDir)})`);
const shaderGenerator = mx.GlslShaderGenerator.create();
const context = new mx.GenContext(shaderGenerator);
const stdlib = mx.loadStandardLibraries(context);
check(stdlib.getNodeDef('ND_open_pbr_surface_surfaceshader') !== null, 'the standard libraries define OpenPBR Surface');
const distance = stdlib.getUnitDef('UD_stdlib_distance');
const millimetre = distance ? distance.getUnit('millimeter') : null;
check(millimetre !== null && Number(millimetre.getAttribute('scale')) === 0.001,
      'the standard libraries define the distance unit "millimeter" as 0.001 m');

async function documentOf(text) {
  const doc = mx.createDocument();
  try {
    await mx.readFromXmlString(doc, text);
  } catch (error) {
    return null;
  }
  doc.setDataLibrary(stdlib);
  return doc;
}

function generatedPixelShader(doc, targetDistanceUnit) {
  context.getOptions().targetDistanceUnit = targetDistanceUnit;
  const element = mx.findRenderableElement(doc);
  const shader = shaderGenerator.generate(element.getNamePath(), element, context);
  return shader.getSourceCode('pixel');
}

fs.mkdirSync(scratch, { recursive: true });
let wax = null;
for (const preset of ['clear-coat-red', 'skin-fair', 'jade', 'paper-thin', 'wax']) {
  const file = path.join(scratch, `${preset}.mtlx`);
  execFileSync(skinlayer, ['export', '--format', 'mtlx', '--preset', preset, '-o', file], { stdio: 'ignore' });
  const text = fs.readFileSync(file, 'utf8');
  if (preset === 'wax') wax = text;
  const doc = await documentOf(text);
  check(doc !== null, `${preset}: reads`);
  if (doc === null) continue;
  check(doc.validate(), `${preset}: validates against the standard libraries`);
  const shader = doc.getNodes().find((node) => node.getCategory() === 'open_pbr_surface');
  check(shader !== undefined && shader.getNodeDef().getName() === 'ND_open_pbr_surface_surfaceshader',
        `${preset}: its shader is ND_open_pbr_surface_surfaceshader`);
  if (shader === undefined) continue;
  const radius = shader.getInput('subsurface_radius');
  check(radius !== null && radius.getUnitType() === 'distance' && radius.getUnit() === 'millimeter',
        `${preset}: subsurface_radius is a distance in millimetres`);
  const unscaled = generatedPixelShader(doc, '');
  const inMetres = generatedPixelShader(doc, 'meter');
  const scale = /uniform float (\w*subsurface_radius_unit\w*) = ([0-9.eE+-]+);/;
  check(unscaled.includes('NG_open_pbr_surface_surfaceshader') && !scale.test(unscaled),
        `${preset}: GLSL generates, the radius as written where no target unit is set`);
  const match = inMetres.match(scale);
  check(match !== null && Number(match[2]) === 0.001 && inMetres.includes(`subsurface_radius * ${match[1]}`),
        `${preset}: with the target unit metres the radius is multiplied by 0.001`);
}

// The directional albedo of a generated ESSL shader under a white environment, per view angle (degrees): runs in
// the page. The shader's inputs come from `values` (name: [type, value string]); a unit's scale uniform is 0.001.
function renderFurnace(vertex, pixel, values, angles, samples) {
  const canvas = document.createElement('canvas');
  const gl = canvas.getContext('webgl2');
  if (!gl || !gl.getExtension('EXT_color_buffer_float')) return { error: 'no WebGL 2 with float targets' };
  const compile = (type, text) => {
    const shader = gl.createShader(type);
    gl.shaderSource(shader, text);
    gl.compileShader(shader);
    if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) throw new Error(gl.getShaderInfoLog(shader));
    return shader;
  };
  const program = gl.createProgram();
  gl.attachShader(program, compile(gl.VERTEX_SHADER, vertex));
  gl.attachShader(program, compile(gl.FRAGMENT_SHADER, pixel));
  gl.linkProgram(program);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS)) return { error: gl.getProgramInfoLog(program) };
  gl.useProgram(program);
  const at = (name) => gl.getUniformLocation(program, name);
  const identity = new Float32Array([1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]);
  for (const name of ['u_worldMatrix', 'u_viewProjectionMatrix', 'u_worldInverseTransposeMatrix', 'u_envMatrix']) {
    gl.uniformMatrix4fv(at(name), false, identity);
  }
  const texture = (unit, size, data) => {
    gl.activeTexture(gl.TEXTURE0 + unit);
    const t = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, t);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, size, size, 0, gl.RGBA, gl.FLOAT, data);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
    return t;
  };
  texture(0, 1, new Float32Array([1, 1, 1, 1]));  // radiance 1 everywhere
  texture(1, 1, new Float32Array([1, 1, 1, 1]));  // its irradiance over pi: 1
  gl.uniform1i(at('u_envRadiance'), 0);
  gl.uniform1i(at('u_envIrradiance'), 1);
  gl.uniform1f(at('u_envLightIntensity'), 1);
  gl.uniform1i(at('u_envRadianceMips'), 1);
  gl.uniform1i(at('u_envRadianceSamples'), samples);
  gl.uniform1i(at('u_numActiveLightSources'), 0);
  for (const [name, [type, text]] of Object.entries(values)) {
    const v = text.split(',').map(Number);
    if (type === 'float') gl.uniform1f(at(name), v[0]);
    if (type === 'color3' || type === 'vector3') gl.uniform3f(at(name), v[0], v[1], v[2]);
    if (type === 'boolean') gl.uniform1i(at(name), text === 'true' ? 1 : 0);
  }
  for (let k = 0; k < gl.getProgramParameter(program, gl.ACTIVE_UNIFORMS); ++k) {
    const name = gl.getActiveUniform(program, k).name;
    if (name.endsWith('_unit_in2')) gl.uniform1f(at(name), 0.001);
  }
  const attribute = (name, data) => {
    const location = gl.getAttribLocation(program, name);
    if (location < 0) return;
    gl.bindBuffer(gl.ARRAY_BUFFER, gl.createBuffer());
    gl.bufferData(gl.ARRAY_BUFFER, new Float32Array(data), gl.STATIC_DRAW);
    gl.enableVertexAttribArray(location);
    gl.vertexAttribPointer(location, 3, gl.FLOAT, false, 0, 0);
  };
  attribute('i_position', [-1, -1, 0, 3, -1, 0, -1, 3, 0]);  // one triangle over the viewport, at z = 0
  attribute('i_normal', [0, 0, 1, 0, 0, 1, 0, 0, 1]);
  attribute('i_tangent', [1, 0, 0, 1, 0, 0, 1, 0, 0]);
  gl.bindFramebuffer(gl.FRAMEBUFFER, gl.createFramebuffer());
  const target = texture(2, 2, null);
  gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, target, 0);
  gl.viewport(0, 0, 2, 2);
  const albedos = [];
  for (const degrees of angles) {
    const theta = (degrees * Math.PI) / 180;  // the camera far away: one view direction for the whole pixel
    gl.uniform3f(at('u_viewPosition'), 1e4 * Math.sin(theta), 0, 1e4 * Math.cos(theta));
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    const pixels = new Float32Array(16);
    gl.readPixels(0, 0, 2, 2, gl.RGBA, gl.FLOAT, pixels);
    albedos.push([pixels[0], pixels[1], pixels[2]]);
  }
  return { albedos };
}

async function furnace(browser, preset, doc) {
  const essl = mx.EsslShaderGenerator.create();
  const esslContext = new mx.GenContext(essl);
  mx.loadStandardLibraries(esslContext);
  const options = esslContext.getOptions();
  options.hwSpecularEnvironmentMethod = mx.HwSpecularEnvironmentMethod.SPECULAR_ENVIRONMENT_FIS;
  options.hwDirectionalAlbedoMethod = mx.HwDirectionalAlbedoMethod.DIRECTIONAL_ALBEDO_ANALYTIC;
  options.hwSrgbEncodeOutput = false;
  options.targetDistanceUnit = 'meter';
  const element = mx.findRenderableElement(doc);
  const shader = essl.generate(element.getNamePath(), element, esslContext);
  const node = doc.getNodes().find((n) => n.getCategory() === 'open_pbr_surface');
  const values = {};
  for (const input of node.getNodeDef().getActiveInputs()) {
    const own = node.getInput(input.getName());
    values[input.getName()] = [input.getType(), (own ? own : input).getValueString()];
  }
  // The fit's report rides in the shader's doc: the fitted model's albedo at its angles is what MaterialX must show.
  const report = JSON.parse(node.getAttribute('doc').replace(/^skinlayer fit /, ''));
  const angles = report.albedo.degrees;
  const page = await browser.newPage();
  const result = await page.evaluate(renderFurnace, shader.getSourceCode('vertex'), shader.getSourceCode('pixel'),
                                     values, angles, 1024);
  await page.close();
  if (result.error) {
    check(false, `${preset}: MaterialX's shader renders (${result.error})`);
    return;
  }
  const csv = execFileSync(skinlayer, ['albedo', '--preset', preset, '--theta-i', angles.join(',')], { encoding: 'utf8' })
                  .trim().split('\n').map((line) => line.split(','));
  const column = (name) => csv[0].indexOf(name);
  const rgb = ['_r', '_g', '_b'].map((c) => (column(`reflectance${c}`) >= 0 ? column(`reflectance${c}`)
                                                                          : column('reflectance')));
  angles.forEach((degrees, k) => {
    const material = rgb.map((c) => Number(csv[k + 1][c]));
    const rendered = result.albedos[k];
    const text = (v) => v.map((x) => x.toFixed(5)).join(' ');
    const fitted = report.albedo.fitted[k];
    console.log(`     ${preset} at ${degrees} degrees: MaterialX ${text(rendered)}, skinlayer's OpenPBR ` +
                `${text(fitted)}, material ${text(material)}`);
    const fromModel = Math.max(...rendered.map((x, c) => Math.abs(x / fitted[c] - 1)));
    check(fromModel < 0.005, `${preset} at ${degrees} degrees: MaterialX's furnace is skinlayer's model of the ` +
                             `fitted surface (worst ${(100 * fromModel).toFixed(3)}%)`);
    if (degrees === 0) {
      const worst = Math.max(...rendered.map((x, c) => Math.abs(x / material[c] - 1)));
      check(worst < 0.005, `${preset}: MaterialX's furnace at normal incidence is the material's albedo ` +
                           `(worst ${(100 * worst).toFixed(3)}%)`);
    }
  });
}

if (furnaceFlag) {
  const puppeteer = createRequire(path.join(path.resolve(furnaceModules), 'noop.js'))('puppeteer-core');
  const browser = await puppeteer.launch({
    executablePath: chromium,
    headless: true,
    args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist'],
  });
  try {
    for (const preset of ['clear-coat-red', 'skin-fair', 'jade', 'paper-thin', 'wax']) {
      const doc = await documentOf(fs.readFileSync(path.join(scratch, `${preset}.mtlx`), 'utf8'));
      await furnace(browser, preset, doc);
    }
  } finally {
    await browser.close();
  }
}

// Each way of breaking the file fails.
const broken = [
  ['an unknown input', 'name="fuzz_weight"', 'name="fuzz_wieght"'],
  ['a wrong type', 'name="coat_weight" type="float"', 'name="coat_weight" type="color3"'],
  ['an unknown unit', 'unit="millimeter"', 'unit="furlong"'],
  ['a wrong unit type', 'unittype="distance"', 'unittype="angle"'],
  ['a material naming no shader', 'nodename="SR_wax"', 'nodename="SR_other"'],
];
for (const [what, from, to] of broken) {
  check(wax.includes(from), `wax: holds ${from}`);
  const doc = await documentOf(wax.replace(from, to));
  check(doc === null || !doc.validate(), `wax with ${what}: does not validate`);
}

console.log(failures === 0 ? 'all checks hold' : `${failures} check(s) failed`);
process.exit(failures === 0 ? 0 : 1);
