// node check_setup.mjs: fails, saying to run scripts/setup.sh, unless tests/clients/node_modules
// holds the exact versions package-lock.json pins.
import fs from 'node:fs';
import path from 'node:path';
import { fail, here } from './common.mjs';

const lock = JSON.parse(fs.readFileSync(path.join(here, 'package-lock.json'), 'utf8'));
for (const [where, entry] of Object.entries(lock.packages)) {
  if (!where) continue;
  const manifest = path.join(here, where, 'package.json');
  if (!fs.existsSync(manifest)) fail(`${path.join(here, where)} is missing: run scripts/setup.sh (or \`npm ci\` in tests/clients)`);
  const version = JSON.parse(fs.readFileSync(manifest, 'utf8')).version;
  if (version !== entry.version) fail(`${where} is ${version}, package-lock.json pins ${entry.version}: run scripts/setup.sh`);
}
console.log(`tests/clients: Node ${process.version}; ${Object.keys(lock.packages).filter(Boolean).map((w) => `${w.replace('node_modules/', '')} ${lock.packages[w].version}`).join(', ')}`);
