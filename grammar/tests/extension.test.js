// The extension's wiring, without VS Code: `vscode` is replaced by a fake, and the language client
// is vscode-languageclient's own, built but not started. Run by `npm test`.
"use strict";

const assert = require("assert");
const Module = require("module");
const path = require("path");

const settings = { path: "/opt/venv/bin/physc" };
const fakeVscode = {
  workspace: {
    getConfiguration: (section) => {
      assert.strictEqual(section, "physc");
      return { get: (key) => settings[key] };
    },
    onDidChangeConfiguration: () => ({ dispose() {} }),
  },
  window: { showErrorMessage: (message) => fakeVscode.shown.push(message) },
  commands: { registerCommand: (name) => ({ name, dispose() {} }) },
  shown: [],
};
const resolve = Module._resolveFilename;
Module._resolveFilename = function (request, ...rest) {
  return request === "vscode" ? "vscode" : resolve.call(this, request, ...rest);
};
// The language client's modules extend and read many vscode classes when they load: any name the
// fake lacks is an empty class.
const vscodeModule = new Proxy(fakeVscode, {
  get: (target, name) => (name in target ? target[name] : (target[name] = class {})),
});
require.cache.vscode = { id: "vscode", filename: "vscode", loaded: true, exports: vscodeModule };
const languageclient = require("vscode-languageclient/node");

// The server command: the setting, then `lsp` (the client adds --stdio, which `physc lsp` accepts).
// The sources by default; `node tests/extension.test.js dist/extension.js` tests the bundle.
const tested = process.argv[2] || "extension.js";
const extension = require(path.join(__dirname, "..", tested));
const options = extension.serverOptions(fakeVscode.workspace.getConfiguration("physc"));
assert.deepStrictEqual(options.run, { command: "/opt/venv/bin/physc", args: ["lsp"], transport: languageclient.TransportKind.stdio });
settings.path = "";
assert.strictEqual(extension.serverOptions(fakeVscode.workspace.getConfiguration("physc")).run.command, "physc");

// package.json: activation on .phys files, the setting, the entry point.
const manifest = require(path.join(__dirname, "..", "package.json"));
assert.ok(manifest.activationEvents.includes("onLanguage:phys"));
assert.strictEqual(manifest.contributes.configuration.properties["physc.path"].default, "physc");
assert.strictEqual(manifest.main, "./dist/extension.js");  // the bundle of extension.js (npm run bundle)
console.log(`extension (${tested}): ok`);
