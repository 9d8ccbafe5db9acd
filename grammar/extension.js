// The VS Code extension for .phys files: the TextMate grammar (package.json) and the physc
// language server, started as `<physc.path> lsp --stdio` (vscode-languageclient).
"use strict";

const vscode = require("vscode");
const { LanguageClient, TransportKind } = require("vscode-languageclient/node");

let client;

/** How to start the server: the `physc.path` setting (default `physc`, found on PATH). */
function serverOptions(configuration) {
  const command = configuration.get("path") || "physc";
  const run = { command, args: ["lsp"], transport: TransportKind.stdio };
  return { run, debug: run };
}

async function start(context) {
  const configuration = vscode.workspace.getConfiguration("physc");
  client = new LanguageClient(
    "physc",
    "physc language server",
    serverOptions(configuration),
    { documentSelector: [{ language: "phys" }] }
  );
  try {
    await client.start();
  } catch (error) {
    const path = configuration.get("path") || "physc";
    vscode.window.showErrorMessage(
      `physc: cannot start the language server with '${path} lsp' (${error.message || error}). ` +
        "Install it with `pip install -e '.[lsp]'` in physc's checkout, or set physc.path to the physc executable."
    );
    client = undefined;
  }
}

async function activate(context) {
  await start(context);
  context.subscriptions.push(
    vscode.workspace.onDidChangeConfiguration(async (event) => {
      if (event.affectsConfiguration("physc.path")) {
        await deactivate();
        await start(context);
      }
    }),
    vscode.commands.registerCommand("physc.restartServer", async () => {
      await deactivate();
      await start(context);
    })
  );
}

async function deactivate() {
  if (client) {
    const stopping = client;
    client = undefined;
    await stopping.stop();
  }
}

module.exports = { activate, deactivate, serverOptions };
