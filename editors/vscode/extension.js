// The VS Code side of ramus: starts `ramus lsp` (the path from the setting ramus.path) on stdio
// and hands it every .ramus document; highlighting comes from syntaxes/ramus.tmLanguage.json.
const vscode = require("vscode");
const { LanguageClient, TransportKind } = require("vscode-languageclient/node");

let client;

function activate(context) {
  const command = vscode.workspace.getConfiguration("ramus").get("path", "ramus");
  const server = { command, args: ["lsp"], transport: TransportKind.stdio };
  client = new LanguageClient(
    "ramus",
    "ramus language server",
    { run: server, debug: server },
    {
      documentSelector: [
        { scheme: "file", language: "ramus" },
        { scheme: "untitled", language: "ramus" },
      ],
    }
  );
  context.subscriptions.push(client);
  return client.start();
}

function deactivate() {
  return client ? client.stop() : undefined;
}

module.exports = { activate, deactivate };
