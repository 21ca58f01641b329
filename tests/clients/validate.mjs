// node validate.mjs FILE.glb|FILE.gltf
// The Khronos glTF validator on an exported file (and, for .gltf, the .bin and images beside it):
// fails unless it reports no errors and no warnings; prints the counts, infos and hints too.
import fs from 'node:fs';
import path from 'node:path';
import { fail, need, usage } from './common.mjs';

usage('node validate.mjs FILE.glb|FILE.gltf', process.argv.length === 3);
const file = process.argv[2];
if (!fs.existsSync(file)) fail(`${file} does not exist`);
const validator = await need('gltf-validator');
const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
  uri: path.basename(file),
  maxIssues: 0,  // all of them
  externalResourceFunction: (uri) => new Promise((resolve, reject) => {
    const resource = path.resolve(path.dirname(file), decodeURIComponent(uri));
    fs.readFile(resource, (error, data) => error ? reject(error.message) : resolve(new Uint8Array(data)));
  }),
});
const issues = report.issues;
const severities = ['error', 'warning', 'info', 'hint'];
for (const message of issues.messages)
  console.log(`  ${severities[message.severity]} ${message.code} at ${message.pointer ?? '-'}: ${message.message}`);
const info = report.info ?? {};
console.log(`${file}: ${issues.numErrors} errors, ${issues.numWarnings} warnings, ${issues.numInfos} infos, ${issues.numHints} hints` +
            ` (validator ${report.validatorVersion}; ${info.extensionsUsed?.length ?? 0} extensions used: ${(info.extensionsUsed ?? []).join(', ')})`);
if (issues.numErrors > 0 || issues.numWarnings > 0)
  fail(`${file}: the validator reports ${issues.numErrors} errors and ${issues.numWarnings} warnings`);
