// The rts extension: starts `rts lsp` (the language server built into the rts binary)
// for .rts/.pov/.inc files. Highlighting comes from the TextMate grammar; everything
// else (diagnostics, hover, completion, navigation, outline, semantic colours) from
// the server.
"use strict";

const vscode = require("vscode");
const { LanguageClient } = require("vscode-languageclient/node");

let client;

function serverOptions() {
  const config = vscode.workspace.getConfiguration("rts");
  const command = config.get("path") || "rts";
  const args = ["lsp"];
  for (const dir of config.get("includeDirs") || []) {
    args.push("-I", dir);
  }
  return { command, args };
}

async function start(context) {
  client = new LanguageClient(
    "rts",
    "rts language server",
    serverOptions(),
    {
      documentSelector: [{ scheme: "file", language: "rts" }],
      outputChannelName: "rts",
    }
  );
  try {
    await client.start();
  } catch (e) {
    vscode.window.showErrorMessage(
      `Could not start \`${serverOptions().command} lsp\`: ${e.message}. ` +
        "Install rts (cargo install --path .) or set rts.path in the settings."
    );
  }
}

async function activate(context) {
  context.subscriptions.push(
    vscode.commands.registerCommand("rts.restartServer", async () => {
      if (client) {
        await client.stop();
      }
      await start(context);
    }),
    vscode.workspace.onDidChangeConfiguration(async (e) => {
      if (e.affectsConfiguration("rts.path") || e.affectsConfiguration("rts.includeDirs")) {
        await vscode.commands.executeCommand("rts.restartServer");
      }
    })
  );
  await start(context);
}

async function deactivate() {
  if (client) {
    await client.stop();
  }
}

module.exports = { activate, deactivate };
