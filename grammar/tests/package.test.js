// The extension packs as the Marketplace wants it, without a warning: `vsce package` (after the
// esbuild bundle) gives a .vsix of the bundle, grammar, manifest, README, LICENSE and icon. Run by
// `npm test`.
"use strict";

const assert = require("assert");
const { execSync } = require("child_process");
const fs = require("fs");
const os = require("os");
const path = require("path");

const root = path.join(__dirname, "..");
const folder = fs.mkdtempSync(path.join(os.tmpdir(), "physc-vsix-"));
const out = path.join(folder, "phys.vsix");
let said, size;
try {
  said = execSync(`npx vsce package --allow-missing-repository --out ${out} 2>&1`, { cwd: root, encoding: "utf8" });
  size = fs.statSync(out).size;
} finally {
  fs.rmSync(folder, { recursive: true, force: true }); // nothing left behind
}
assert.ok(!/WARNING/i.test(said), `vsce warned:\n${said}`);
assert.ok(size > 0);
for (const file of ["dist/extension.js", "LICENSE.txt", "icon.png", "readme.md", "syntaxes/phys.tmLanguage.json"]) {
  assert.ok(said.includes(path.basename(file)), `the package lacks ${file}:\n${said}`);
}
assert.ok(!said.includes("node_modules"), "node_modules went into the package: the bundle should hold the client");

// The bundle starts the server as the sources do (the same wiring test, on dist/extension.js).
const manifest = JSON.parse(fs.readFileSync(path.join(root, "package.json"), "utf8"));
assert.strictEqual(manifest.main, "./dist/extension.js");
assert.strictEqual(manifest.capabilities.untrustedWorkspaces.supported, "limited");
assert.deepStrictEqual(manifest.capabilities.untrustedWorkspaces.restrictedConfigurations, ["physc.path"]);
assert.ok(!fs.existsSync(folder), "the package's temporary folder was left behind");
console.log("package: ok");
