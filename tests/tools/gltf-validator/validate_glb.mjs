// Prints the Khronos glTF validator's JSON report of one .glb file.
// Usage: node validate_glb.mjs FILE.glb
import { readFile } from 'node:fs/promises';
import validator from 'gltf-validator';

const path = process.argv[2];
if (!path) {
  console.error('usage: node validate_glb.mjs FILE.glb');
  process.exit(2);
}
const bytes = new Uint8Array(await readFile(path));
// External resources are refused: a hull file carries everything itself.
const report = await validator.validateBytes(bytes, {
  uri: path,
  maxIssues: 1000,
  externalResourceFunction: (uri) => Promise.reject(new Error('external resource ' + uri)),
});
process.stdout.write(JSON.stringify(report, null, 1) + '\n');
