// The uprog extension's entry: starts `uprog lsp` (uprog.path) as the language server of the
// four dialects' files; the TextMate grammars colour them until its semantic tokens arrive, and
// the debugger (contributes.debuggers) runs `uprog dap` on its own.
'use strict';
const vscode = require('vscode');
const { LanguageClient, TransportKind } = require('vscode-languageclient/node');

const LANGUAGES = ['elmo-gold', 'hiwin-pdl', 'akribis-pup', 'kollmorgen-st'];
let client;

function start() {
  const command = vscode.workspace.getConfiguration('uprog').get('path') || 'uprog';
  const run = { command, args: ['lsp'], transport: TransportKind.stdio };
  client = new LanguageClient(
    'uprog',
    'uprog',
    { run, debug: run },
    {
      documentSelector: LANGUAGES.map((language) => ({ language })),
      synchronize: { fileEvents: vscode.workspace.createFileSystemWatcher('**/*.{h,puh}') },
    });
  return client.start().catch((error) => {
    vscode.window.showErrorMessage(
      `uprog: could not start '${command} lsp' (${error.message}); set uprog.path to the uprog ` +
      'executable.');
  });
}

async function activate(context) {
  context.subscriptions.push(vscode.workspace.onDidChangeConfiguration(async (event) => {
    if (!event.affectsConfiguration('uprog.path')) return;
    if (client) await client.stop();
    await start();
  }));
  await start();
}

function deactivate() {
  return client ? client.stop() : undefined;
}

module.exports = { activate, deactivate };
