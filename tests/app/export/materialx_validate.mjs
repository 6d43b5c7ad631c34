// `skinlayer export --format mtlx` read by MaterialX itself: the WebAssembly build of MaterialX's core and shader
// generation that the npm package @needle-tools/materialx ships (bin/JsMaterialXGenShader.js with the standard
// libraries packed beside it, MaterialX 1.39.4 in its 1.4.6). For a few presets the exported file must
//   - read, and validate against the standard libraries (Document.validate: every input known to the node
//     definition, of its type, every unit known to its unit type, the material naming its shader);
//   - bind its shader to ND_open_pbr_surface_surfaceshader;
//   - carry subsurface_radius in millimetres (unittype "distance", unit "millimeter"), a unit the standard library
//     defines at 0.001 m;
//   - generate GLSL, and, with the generator's target distance unit set to metres, scale the radius by 0.001 (without
//     a target unit the radius enters the shader as written, in whatever unit the scene has).
// And a file broken in each of those ways must fail (the check is not one that passes anything).
//
// Usage: node materialx_validate.mjs PACKAGE_DIR SKINLAYER_EXECUTABLE SCRATCH_DIR
//   PACKAGE_DIR: node_modules/@needle-tools/materialx. Exit status 0 when every check holds, 1 otherwise, 2 on bad
//   arguments; one line per check on stdout.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import { createRequire } from 'node:module';
import path from 'node:path';

const [packageDir, skinlayer, scratch] = process.argv.slice(2);
if (!packageDir || !skinlayer || !scratch) {
  console.error('usage: node materialx_validate.mjs PACKAGE_DIR SKINLAYER_EXECUTABLE SCRATCH_DIR');
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
