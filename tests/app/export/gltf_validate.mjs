// Runs Khronos' glTF-Validator (the npm package gltf-validator) on .gltf files and prints, per file, the counts of
// errors, warnings, infos and hints and each message. Exits 1 if any file has an error or a warning, 2 on bad use.
//   node gltf_validate.mjs --tools <node_modules holding gltf-validator> file.gltf...
// The tools folder may also come from the environment, SKINLAYER_GLTF_TOOLS.
import { readFile } from 'node:fs/promises';
import { createRequire } from 'node:module';
import path from 'node:path';

const args = process.argv.slice(2);
let tools = process.env.SKINLAYER_GLTF_TOOLS ?? '';
const files = [];
for (let k = 0; k < args.length; ++k) {
  if (args[k] === '--tools') tools = args[++k] ?? '';
  else files.push(args[k]);
}
if (!tools || files.length === 0) {
  console.error('usage: node gltf_validate.mjs --tools <node_modules> file.gltf...');
  process.exit(2);
}
const require = createRequire(import.meta.url);
const validator = require(path.resolve(tools, 'gltf-validator'));

let failed = false;
for (const file of files) {
  const bytes = await readFile(file);
  const report = await validator.validateBytes(new Uint8Array(bytes), {
    uri: path.basename(file),
    format: 'gltf',
    maxIssues: 0,  // all of them
    // Data URIs only: any other resource is a failure of the export.
    externalResourceFunction: (uri) => Promise.reject(new Error(`external resource ${uri}: the export embeds all`)),
  });
  const issues = report.issues;
  console.log(`${file}: validator ${report.validatorVersion}: ${issues.numErrors} errors, ${issues.numWarnings} ` +
              `warnings, ${issues.numInfos} infos, ${issues.numHints} hints`);
  for (const message of issues.messages) {
    const severity = ['error', 'warning', 'info', 'hint'][message.severity] ?? message.severity;
    console.log(`  ${severity} ${message.code} at ${message.pointer ?? ''}: ${message.message}`);
  }
  const info = report.info ?? {};
  console.log(`  extensionsUsed: ${JSON.stringify(info.extensionsUsed ?? [])}, ` +
              `drawCallCount ${info.drawCallCount}, totalVertexCount ${info.totalVertexCount}, ` +
              `totalTriangleCount ${info.totalTriangleCount}, materialCount ${info.materialCount}`);
  if (issues.numErrors > 0 || issues.numWarnings > 0) failed = true;
}
process.exit(failed ? 1 : 0);
