// The end-to-end scenario of `uprog dap` with a real DAP client (@vscode/debugadapter-testsupport),
// run by `node --test` from ctest (tests/debug/CMakeLists.txt): stop at a breakpoint in a Gold
// function, read a local and a global, step over, step into a function and out, a conditional
// breakpoint that stops on the third hit, set a variable and see the program use it, break on a
// division by zero, continue to the end. UPROG names the uprog binary.
'use strict';
const { test, before, after } = require('node:test');
const assert = require('node:assert');
const path = require('node:path');
const { DebugClient } = require('@vscode/debugadapter-testsupport');

const uprog = process.env.UPROG;
const program = path.resolve(__dirname, 'programs', 'scenario.ehl');
let dc;

before(async () => {
  assert.ok(uprog, 'UPROG must name the uprog binary');
  dc = new DebugClient(uprog, 'dap', 'uprog');
  await dc.start();
});

after(async () => {
  await dc.stop();
});

async function variable(frameId, scopeName, name) {
  const scopes = await dc.scopesRequest({ frameId });
  const scope = scopes.body.scopes.find((s) => s.name === scopeName);
  assert.ok(scope, `no scope ${scopeName}`);
  const vars = await dc.variablesRequest({ variablesReference: scope.variablesReference });
  const v = vars.body.variables.find((x) => x.name === name);
  assert.ok(v, `no variable ${name} in ${scopeName}`);
  return { value: v.value, reference: scope.variablesReference };
}

async function topFrame() {
  const trace = await dc.stackTraceRequest({ threadId: 1 });
  return trace.body.stackFrames[0];
}

async function stepAndExpect(request, line, name) {
  await Promise.all([dc[request]({ threadId: 1 }), dc.assertStoppedLocation('step', { path: program, line })]);
  const frame = await topFrame();
  assert.strictEqual(frame.name, name);
  return frame;
}

test('a Gold debugging session from breakpoint to the end', async () => {
  // Start and stop at a breakpoint inside the function add (line 19: s = c).
  await dc.hitBreakpoint({ program, dialect: 'gold' }, { path: program, line: 19 });
  let frame = await topFrame();
  assert.strictEqual(frame.name, 'add');
  // A local and a global: the first call, add(0, 1).
  assert.strictEqual((await variable(frame.id, 'Locals', 'c')).value, '1');
  assert.strictEqual((await variable(frame.id, 'Globals', 'total')).value, '0');

  // Step over: to the function's last line.
  await stepAndExpect('nextRequest', 20, 'add');

  // A conditional breakpoint in main's loop that stops on the third hit, when i is 3.
  await dc.setBreakpointsRequest({ source: { path: program }, breakpoints: [] });
  const set = await dc.setBreakpointsRequest({ source: { path: program }, breakpoints: [{ line: 11, condition: 'i == 3' }] });
  assert.strictEqual(set.body.breakpoints[0].verified, true);
  await Promise.all([dc.continueRequest({ threadId: 1 }), dc.assertStoppedLocation('breakpoint', { path: program, line: 11 })]);
  frame = await topFrame();
  assert.strictEqual((await variable(frame.id, 'Locals', 'i')).value, '3');
  assert.strictEqual((await variable(frame.id, 'Globals', 'total')).value, '3');  // 1 + 2 so far

  // Into add and out again.
  await stepAndExpect('stepInRequest', 18, 'add');
  frame = await stepAndExpect('stepOutRequest', 12, 'main');
  assert.strictEqual((await variable(frame.id, 'Globals', 'total')).value, '6');

  // Set variables: total, which the loop goes on adding to, and divisor, which makes the
  // division after the loop divide by zero.
  await dc.setBreakpointsRequest({ source: { path: program }, breakpoints: [] });
  const globals = (await variable(frame.id, 'Globals', 'total')).reference;
  const setTotal = await dc.setVariableRequest({ variablesReference: globals, name: 'total', value: '100' });
  assert.strictEqual(setTotal.body.value, '100');
  await dc.setVariableRequest({ variablesReference: globals, name: 'divisor', value: '0' });

  // Break on the run-time error: the division by zero at line 13.
  await dc.setExceptionBreakpointsRequest({ filters: ['error'] });
  const [, stopped] = await Promise.all([dc.continueRequest({ threadId: 1 }), dc.waitForEvent('stopped')]);
  assert.strictEqual(stopped.body.reason, 'exception');
  assert.match(stopped.body.description, /division by zero/i);
  frame = await topFrame();
  assert.strictEqual(frame.line, 13);
  // The program used the value set: 100 + 4 + 5.
  assert.strictEqual((await variable(frame.id, 'Globals', 'total')).value, '109');
  const evaluated = await dc.evaluateRequest({ expression: 'total - 100', frameId: frame.id, context: 'watch' });
  assert.strictEqual(evaluated.body.result, '9');

  // Continue to the end: the program stopped by its error, exit code 1.
  const [, exited] = await Promise.all([
    dc.continueRequest({ threadId: 1 }),
    dc.waitForEvent('exited'),
    dc.waitForEvent('terminated'),
  ]);
  assert.strictEqual(exited.body.exitCode, 1);
});

test('the same client over TCP: uprog dap --listen', async () => {
  const { spawn } = require('node:child_process');
  const server = spawn(uprog, ['dap', '--listen', '127.0.0.1:0'], { stdio: ['ignore', 'ignore', 'pipe'] });
  try {
    const port = await new Promise((resolve, reject) => {
      let text = '';
      server.stderr.on('data', (d) => {
        text += d;
        const m = /listening on tcp [0-9.]+:(\d+)/.exec(text);
        if (m) resolve(Number(m[1]));
      });
      server.on('exit', (code) => reject(new Error(`uprog dap exited (${code}): ${text}`)));
    });
    const tcp = new DebugClient(uprog, 'dap', 'uprog');
    await tcp.start(port);
    await tcp.hitBreakpoint({ program }, { path: program, line: 18 });
    const trace = await tcp.stackTraceRequest({ threadId: 1 });
    assert.deepStrictEqual(trace.body.stackFrames.map((f) => [f.name, f.line]), [['add', 18], ['main', 11]]);
    // stop() disconnects; the server serves one client and then ends.
    const exited = new Promise((resolve) => server.on('exit', resolve));
    await tcp.stop();
    assert.strictEqual(await exited, 0);
  } finally {
    server.kill();
  }
});
