// The smoke test of `uprog lsp` with a real LSP client's JSON-RPC (vscode-jsonrpc, the library
// VS Code's language client speaks through), run by `node --test` from ctest
// (tests/lsp/CMakeLists.txt): for each dialect, initialize, open a file with an error and get its
// diagnostic (the dialect's code and registered text), hover a drive command, complete, go to a
// function; then a hostile message written straight to the server, which still answers.
'use strict';
const { test, before, after } = require('node:test');
const assert = require('node:assert');
const { spawn } = require('node:child_process');
const rpc = require('vscode-jsonrpc/node');

const uprog = process.env.UPROG;
let server, connection;
const published = new Map();  // uri -> the diagnostics last published
const waiting = new Map();    // uri -> resolve

function diagnosticsOf(uri) {
  if (published.has(uri)) return Promise.resolve(published.get(uri));
  return new Promise((resolve) => waiting.set(uri, resolve));
}

before(async () => {
  assert.ok(uprog, 'UPROG must name the uprog binary');
  server = spawn(uprog, ['lsp', '--stdio'], { stdio: ['pipe', 'pipe', 'inherit'] });
  connection = rpc.createMessageConnection(new rpc.StreamMessageReader(server.stdout),
                                           new rpc.StreamMessageWriter(server.stdin));
  connection.onNotification('textDocument/publishDiagnostics', (p) => {
    published.set(p.uri, p.diagnostics);
    const resolve = waiting.get(p.uri);
    if (resolve) {
      waiting.delete(p.uri);
      resolve(p.diagnostics);
    }
  });
  connection.listen();
  const init = await connection.sendRequest('initialize', {
    processId: process.pid,
    rootUri: null,
    capabilities: { textDocument: { completion: { completionItem: { snippetSupport: true } } } },
  });
  assert.strictEqual(init.capabilities.textDocumentSync.change, 2);
  assert.ok(init.capabilities.hoverProvider);
  connection.sendNotification('initialized', {});
});

after(async () => {
  await connection.sendRequest('shutdown');
  connection.sendNotification('exit');
  const code = await new Promise((resolve) => server.on('exit', resolve));
  assert.strictEqual(code, 0);  // exit after shutdown (LSP 3.17)
  connection.dispose();
});

// Per dialect: a program whose line 2 uses an undeclared name (the code and the registered
// text from the dialect's error table: gold_errors.def 12, pdl errors.def 20, pup_errors.def 2,
// st_errors.def 11), a drive command to hover with words of its reference entry, and a call of
// a user function with where that function is declared.
const cases = [
  {
    dialect: 'gold', languageId: 'elmo-gold', uri: 'file:///smoke/a.ehl',
    text: 'int done\nfunction main()\ndone = missing\nMO = 1\nhelper()\nreturn\n' +
          'function helper()\nreturn\n',
    code: 12, message: 'No such variable', hover: { line: 3, character: 0 }, words: 'motor enable',
    call: { line: 4, character: 1 }, target: 6, keyword: 'while',
  },
  {
    dialect: 'pdl', languageId: 'hiwin-pdl', uri: 'file:///smoke/a.pdl',
    text: '#long done\nproc add(long k) do\n  done=missing;\nend;\n#task/1;\nX_acc=1000;\n' +
          'add(5);\nhalt;\n',
    code: 20, message: 'unknown name', hover: { line: 5, character: 3 }, words: 'acceleration',
    call: { line: 6, character: 0 }, target: 1, keyword: 'while',
  },
  {
    dialect: 'pup', languageId: 'akribis-pup', uri: 'file:///smoke/a.pup',
    text: '#define STEP 1\nAProgTask[1]\nAGenData[1] = Missing\nASpeed = 1000\n' +
          'AProgFuncCall, STEP\nAProgHalt[1]\nAProgFunc[STEP]\nreturn\n',
    code: 2, message: 'unknown name', hover: { line: 3, character: 2 }, words: 'Speed',
    call: { line: 4, character: 16 }, target: 6, keyword: 'while',
  },
  {
    dialect: 'st', languageId: 'kollmorgen-st', uri: 'file:///smoke/a.st',
    text: "LONG DONE ;\nFUNCTION BUMP\n   DONE := MISSING;\nEND_FUNCTION\nPROGRAM PLCMAIN\n" +
          "   XREAD('VLIM', DONE);\n   FUNCTION (BUMP);\nEND_PROGRAM\n",
    code: 11, message: 'variable not declared', hover: { line: 5, character: 11 },
    words: 'Velocity limit', call: { line: 6, character: 14 }, target: 1, keyword: 'WHILE',
  },
];

for (const k of cases) {
  test(`a ${k.dialect} session: diagnostics, hover, completion, definition`, async () => {
    connection.sendNotification('textDocument/didOpen', {
      textDocument: { uri: k.uri, languageId: k.languageId, version: 1, text: k.text },
    });
    const diagnostics = await diagnosticsOf(k.uri);
    assert.ok(diagnostics.length >= 1, JSON.stringify(diagnostics));
    assert.strictEqual(diagnostics[0].code, k.code);
    assert.ok(diagnostics[0].message.startsWith(k.message), diagnostics[0].message);
    assert.strictEqual(diagnostics[0].range.start.line, 2);

    const hover = await connection.sendRequest('textDocument/hover',
                                               { textDocument: { uri: k.uri }, position: k.hover });
    assert.ok(hover && hover.contents.value.includes(k.words), JSON.stringify(hover));
    assert.ok(hover.contents.value.includes('Source:'));

    const list = await connection.sendRequest('textDocument/completion', {
      textDocument: { uri: k.uri }, position: { line: k.call.line, character: 0 },
    });
    assert.ok(list.items.some((i) => i.label === k.keyword), 'no ' + k.keyword);

    const where = await connection.sendRequest('textDocument/definition',
                                               { textDocument: { uri: k.uri }, position: k.call });
    assert.ok(where, 'no definition');
    assert.strictEqual(where.uri, k.uri);
    assert.strictEqual(where.range.start.line, k.target);
  });
}

test('a hostile message gets its error and the server goes on', async () => {
  // Written past the client: a request whose method is a number (JSON-RPC 2.0: -32600).
  const body = '{"jsonrpc":"2.0","id":"hostile","method":7}';
  const answered = new Promise((resolve) => {
    let seen = '';
    const listener = (chunk) => {
      seen += chunk.toString('latin1');
      if (seen.includes('"hostile"')) {
        server.stdout.off('data', listener);
        resolve(seen);
      }
    };
    server.stdout.on('data', listener);
  });
  server.stdin.write(`Content-Length: ${Buffer.byteLength(body)}\r\n\r\n${body}`);
  assert.ok((await answered).includes('-32600'));
  const hover = await connection.sendRequest('textDocument/hover', {
    textDocument: { uri: cases[0].uri }, position: cases[0].hover,
  });
  assert.ok(hover.contents.value.includes(cases[0].words));
});

test('uprog lsp --listen serves one client over TCP', async () => {
  const net = require('node:net');
  const listening = spawn(uprog, ['lsp', '--listen', '127.0.0.1:0'], { stdio: ['ignore', 'ignore', 'pipe'] });
  const port = await new Promise((resolve) => {
    let said = '';
    listening.stderr.on('data', (chunk) => {
      said += chunk;
      const m = said.match(/listening on tcp [0-9.]+:(\d+)/);
      if (m) resolve(Number(m[1]));
    });
  });
  const socket = net.connect(port, '127.0.0.1');
  const tcp = rpc.createMessageConnection(new rpc.SocketMessageReader(socket),
                                          new rpc.SocketMessageWriter(socket));
  tcp.listen();
  const init = await tcp.sendRequest('initialize', { processId: null, rootUri: null, capabilities: {} });
  assert.ok(init.capabilities.definitionProvider);
  await tcp.sendRequest('shutdown');
  tcp.sendNotification('exit');
  assert.strictEqual(await new Promise((resolve) => listening.on('exit', resolve)), 0);
  tcp.dispose();
  socket.destroy();
});
