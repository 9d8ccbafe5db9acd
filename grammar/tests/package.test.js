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
const out = path.join(fs.mkdtempSync(path.join(os.tmpdir(), "physc-vsix-")), "phys.vsix");
const said = execSync(`npx vsce package --allow-missing-repository --out ${out} 2>&1`, { cwd: root, encoding: "utf8" });
assert.ok(!/WARNING/i.test(said), `vsce warned:\n${said}`);
assert.ok(fs.statSync(out).size > 0);
for (const file of ["dist/extension.js", "LICENSE.txt", "icon.png", "readme.md", "syntaxes/phys.tmLanguage.json"]) {
  assert.ok(said.includes(path.basename(file)), `the package lacks ${file}:\n${said}`);
}
assert.ok(!said.includes("node_modules"), "node_modules went into the package: the bundle should hold the client");

// The bundle starts the server as the sources do (the same wiring test, on dist/extension.js).
const manifest = JSON.parse(fs.readFileSync(path.join(root, "package.json"), "utf8"));
assert.strictEqual(manifest.main, "./dist/extension.js");
assert.strictEqual(manifest.capabilities.untrustedWorkspaces.supported, "limited");
assert.deepStrictEqual(manifest.capabilities.untrustedWorkspaces.restrictedConfigurations, ["physc.path"]);
console.log("package: ok");
