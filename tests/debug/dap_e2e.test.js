// The end-to-end scenario of `uprog dap` with a real DAP client (@vscode/debugadapter-testsupport),
// run by `node --test` from ctest (tests/debug/CMakeLists.txt): stop at a breakpoint in a Gold
// function, read a local and a global, step over, step into a function and out, a conditional
// breakpoint that stops on the third hit, set a variable and see the program use it, break on a
// division by zero, continue to the end; then sessions on the other dialects (PUP, PDL, ST), over
// TCP and attached to `uprog sim`. UPROG names the uprog binary.
'use strict';
const { test, before, after } = require('node:test');
const assert = require('node:assert');
const path = require('node:path');
const { DebugClient } = require('@vscode/debugadapter-testsupport');

const uprog = process.env.UPROG;
const program = path.resolve(__dirname, 'programs', 'scenario.ehl');
let dc;

// A client whose requests may take 30 s rather than the library's 5: CI runs this beside the
// other tests on two cores, and under the sanitizers.
function newClient() {
  const client = new DebugClient(uprog, 'dap', 'uprog');
  client.defaultTimeout = 30000;
  return client;
}

before(async () => {
  assert.ok(uprog, 'UPROG must name the uprog binary');
  dc = newClient();
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
    const tcp = newClient();
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

// Attach: `uprog sim --dap` serves the debugger of the program it runs; `uprog dap` attaches to
// it and relays. While the program stands at a breakpoint the sim's time stands still, and its
// command line answers other hosts all along.
async function startSim(programPath) {
  const { spawn } = require('node:child_process');
  const sim = spawn(uprog, ['sim', '--listen', '127.0.0.1:0', '--dap', '127.0.0.1:0', '--wire', 'readable',
    '--program', programPath], { stdio: ['ignore', 'pipe', 'pipe'] });
  const ports = await new Promise((resolve, reject) => {
    let text = '';
    sim.stdout.on('data', (d) => {
      text += d;
      const line = /listening on tcp [0-9.]+:(\d+)/.exec(text);
      const dap = /debugger on tcp [0-9.]+:(\d+)/.exec(text);
      if (line && dap) resolve({ line: Number(line[1]), dap: Number(dap[1]) });
    });
    sim.stderr.on('data', (d) => { text += d; });
    sim.on('exit', (code) => reject(new Error(`uprog sim exited (${code}): ${text}`)));
  });
  return { sim, ...ports };
}

// A host on the sim's command line (the readable wire form): each line's answers up to CR LF.
async function commandLine(port) {
  const net = require('node:net');
  const socket = net.connect(port, '127.0.0.1');
  await new Promise((resolve, reject) => { socket.once('connect', resolve); socket.once('error', reject); });
  let buffered = '';
  const waiting = [];
  socket.on('data', (d) => {
    buffered += d;
    let end;
    while ((end = buffered.indexOf('\r\n')) >= 0 && waiting.length > 0) {
      const answer = buffered.slice(0, end);
      buffered = buffered.slice(end + 2);
      waiting.shift()(answer);
    }
  });
  return {
    ask: (line) => new Promise((resolve) => { waiting.push(resolve); socket.write(line + '\r'); }),
    close: () => socket.destroy(),
  };
}

const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));
// Waits until `check` holds, asking every 50 ms, for at most 20 s of the wall clock: the sim
// paces virtual time to it, and a loaded machine gives the sim its CPU late.
async function until(check, what) {
  const deadline = Date.now() + 20000;
  while (!(await check())) {
    if (Date.now() > deadline) assert.fail(what);
    await sleep(50);
  }
}
const number = (answer) => Number(answer.replace(/;$/, ''));

test('attach to a program running in uprog sim', async () => {
  const attached = path.resolve(__dirname, 'programs', 'attach.ehl');
  const { sim, line, dap } = await startSim(attached);
  const host = await commandLine(line);
  const client = newClient();
  try {
    await client.start();
    // The program runs before anyone debugs it.
    await until(async () => number(await host.ask('ticks')) > 0, 'the program does not run before attaching');
    const before = number(await host.ask('ticks'));

    await client.initializeRequest();
    await Promise.all([client.attachRequest({ host: '127.0.0.1', port: dap }), client.waitForEvent('initialized')]);
    const threads = await client.threadsRequest();
    assert.deepStrictEqual(threads.body.threads.map((t) => t.id), [1]);
    const set = await client.setBreakpointsRequest({ source: { path: attached }, breakpoints: [{ line: 10 }] });
    assert.strictEqual(set.body.breakpoints[0].verified, true);
    await Promise.all([client.configurationDoneRequest(), client.assertStoppedLocation('breakpoint', { path: attached, line: 10 })]);

    // Stopped: the global as the debugger and as the command line see it, and time standing.
    const trace = await client.stackTraceRequest({ threadId: 1 });
    const scopes = await client.scopesRequest({ frameId: trace.body.stackFrames[0].id });
    const globals = scopes.body.scopes.find((s) => s.name === 'Globals');
    const vars = await client.variablesRequest({ variablesReference: globals.variablesReference });
    const ticks = Number(vars.body.variables.find((v) => v.name === 'ticks').value);
    assert.ok(ticks >= before, `ticks ${ticks} at the breakpoint, ${before} before`);
    assert.strictEqual(number(await host.ask('ticks')), ticks);
    const time = number(await host.ask('TM'));
    await sleep(300);
    assert.strictEqual(number(await host.ask('TM')), time, 'virtual time ran on while stopped');
    assert.strictEqual(number(await host.ask('ticks')), ticks);

    // The same breakpoint stops again one round later: one tick more.
    await Promise.all([client.continueRequest({ threadId: 1 }), client.assertStoppedLocation('breakpoint', { path: attached, line: 10 })]);
    const evaluated = await client.evaluateRequest({ expression: 'ticks', frameId: trace.body.stackFrames[0].id, context: 'watch' });
    assert.strictEqual(Number(evaluated.body.result), ticks + 1);

    // Without the breakpoint it runs on, and the command line answers meanwhile.
    await client.setBreakpointsRequest({ source: { path: attached }, breakpoints: [] });
    await client.continueRequest({ threadId: 1 });
    await until(async () => number(await host.ask('ticks')) > ticks + 5, 'the program did not go on after continue');
    await until(async () => number(await host.ask('TM')) > time + 100000, 'virtual time did not go on after continue');

    // Disconnecting leaves the program running in the sim.
    await client.stop();
    const detached = number(await host.ask('ticks'));
    await until(async () => number(await host.ask('ticks')) > detached, 'the program stopped when the debugger left');
  } finally {
    host.close();
    sim.kill();
  }
});

// PUP (Akribis AG300): the debug map takes a breakpoint to the PUP line, threads 1..8 show by
// their names, Globals hold the #definevar variables, evaluate reads PUP, and a singleThread
// step moves thread 2 alone.
test('a PUP session on two threads', async () => {
  const pup = path.resolve(__dirname, 'programs', 'two_threads.pup');
  const client = newClient();
  await client.start();
  try {
    await client.hitBreakpoint({ program: pup }, { path: pup, line: 12 });
    const threads = await client.threadsRequest();
    assert.deepStrictEqual(threads.body.threads.map((t) => t.name),
      ['thread 1', 'thread 2', 'thread 3', 'thread 4', 'thread 5', 'thread 6', 'thread 7', 'thread 8']);
    const two = threads.body.threads[1].id;
    // The first hit comes before either thread has counted; the second one round later.
    await Promise.all([client.continueRequest({ threadId: two }), client.assertStoppedLocation('breakpoint', { path: pup, line: 12 })]);
    const trace = await client.stackTraceRequest({ threadId: two });
    assert.deepStrictEqual(trace.body.stackFrames.map((f) => [f.name, f.line]), [['task 2', 12]]);
    const frameId = trace.body.stackFrames[0].id;
    const scopes = await client.scopesRequest({ frameId });
    const globals = scopes.body.scopes.find((s) => s.name === 'Globals');
    const vars = await client.variablesRequest({ variablesReference: globals.variablesReference });
    const byName = Object.fromEntries(vars.body.variables.map((v) => [v.name, v.value]));
    assert.strictEqual(byName.Two, '1');
    const one = Number(byName.One);
    assert.ok(one >= 1, `One is ${byName.One}`);
    const sum = await client.evaluateRequest({ expression: 'One * 2 + Two + 1', frameId, context: 'watch' });
    assert.strictEqual(sum.body.result, String(one * 2 + 2));

    // Thread 2 alone, round its loop: Two counts, One stands.
    await client.setBreakpointsRequest({ source: { path: pup }, breakpoints: [] });
    for (let i = 0; i < 4; i++) {
      const [, stopped] = await Promise.all([client.nextRequest({ threadId: two, singleThread: true }), client.waitForEvent('stopped')]);
      assert.strictEqual(stopped.body.reason, 'step');
      assert.strictEqual(stopped.body.threadId, two);
    }
    const after = await client.evaluateRequest({ expression: 'One', frameId, context: 'watch' });
    assert.strictEqual(after.body.result, String(one));
    const counted = await client.evaluateRequest({ expression: 'Two', frameId, context: 'watch' });
    assert.ok(Number(counted.body.result) >= 2, `Two is ${counted.body.result} after four steps`);
  } finally {
    await client.stop();
  }
});

test('a PDL session: procedures in an included file, the tasks as threads', async () => {
  const dir = path.resolve(__dirname, '..', 'transcripts', 'debug', 'programs');
  const pdl = path.join(dir, 'pdl_debug.pdl');
  const scale = path.join(dir, 'pdl', 'scale.h');
  const client = newClient();
  await client.start();
  try {
    // twice's first line, called from scale, called from task 1
    await client.hitBreakpoint({ program: pdl }, { path: scale, line: 5 });
    const threads = await client.threadsRequest();
    assert.deepStrictEqual(threads.body.threads.map((t) => t.name), ['task 1', 'task 2', 'task 3']);
    const task1 = threads.body.threads[0].id;
    let trace = await client.stackTraceRequest({ threadId: task1 });
    assert.deepStrictEqual(trace.body.stackFrames.map((f) => [f.name, f.line]), [['twice', 5], ['scale', 12], ['_t1', 11]]);
    const scaleFrame = trace.body.stackFrames[1].id;
    const scopes = await client.scopesRequest({ frameId: scaleFrame });
    const locals = scopes.body.scopes.find((s) => s.name === 'Locals');
    const vars = await client.variablesRequest({ variablesReference: locals.variablesReference });
    assert.deepStrictEqual(vars.body.variables.map((v) => [v.name, v.value]),
      [['v', '1'], ['k', '3'], ['res', '1'], ['prod', '3'], ['half', '0.0']]);
    const product = await client.evaluateRequest({ expression: 'v*k+count', frameId: scaleFrame, context: 'watch' });
    assert.strictEqual(product.body.result, '4');

    // Out of twice, then over the rest of scale and out of it: total is 2 * 3 * count.
    await client.setBreakpointsRequest({ source: { path: scale }, breakpoints: [] });
    await Promise.all([client.stepOutRequest({ threadId: task1 }), client.assertStoppedLocation('step', { path: scale, line: 13 })]);
    await Promise.all([client.stepOutRequest({ threadId: task1 }), client.assertStoppedLocation('step', { path: pdl, line: 12 })]);
    trace = await client.stackTraceRequest({ threadId: task1 });
    const top = trace.body.stackFrames[0].id;
    const total = await client.evaluateRequest({ expression: 'total', frameId: top, context: 'watch' });
    assert.strictEqual(total.body.result, '6');

    // A condition in PDL (`=` compares), then a global set and used.
    await client.setBreakpointsRequest({ source: { path: scale }, breakpoints: [{ line: 11, condition: 'v = 3' }] });
    await Promise.all([client.continueRequest({ threadId: task1 }), client.assertStoppedLocation('breakpoint', { path: scale, line: 11 })]);
    trace = await client.stackTraceRequest({ threadId: task1 });
    const globals = (await client.scopesRequest({ frameId: trace.body.stackFrames[0].id })).body.scopes.find((s) => s.name === 'Globals');
    const set = await client.setVariableRequest({ variablesReference: globals.variablesReference, name: 'count', value: '20' });
    assert.strictEqual(set.body.value, '20');
    await client.setBreakpointsRequest({ source: { path: scale }, breakpoints: [] });
    await client.setBreakpointsRequest({ source: { path: pdl }, breakpoints: [{ line: 13 }] });
    await Promise.all([client.continueRequest({ threadId: task1 }), client.assertStoppedLocation('breakpoint', { path: pdl, line: 13 })]);
    const after = await client.evaluateRequest({ expression: 'total', frameId: (await client.stackTraceRequest({ threadId: task1 })).body.stackFrames[0].id, context: 'watch' });
    assert.strictEqual(after.body.result, '18');  // this round's scale still had v = 3
  } finally {
    await client.stop();
  }
});

test('an ST session: a FUNCTION called from PLC1, the PLC programs as threads', async () => {
  const st = path.resolve(__dirname, 'programs', 'scenario.st');
  const client = newClient();
  await client.start();
  const top = async (threadId) => (await client.stackTraceRequest({ threadId })).body.stackFrames[0];
  const evaluate = async (expression, frameId) =>
    (await client.evaluateRequest({ expression, frameId, context: 'watch' })).body.result;
  // A scope's reference holds for the stop it came from.
  const globalsOf = async (frameId) =>
    (await client.scopesRequest({ frameId })).body.scopes.find((s) => s.name === 'Globals').variablesReference;
  try {
    // PLC1's first run, before it calls TWICE (ST has no locals: the globals are its variables).
    await client.hitBreakpoint({ program: st }, { path: st, line: 12 });
    const threads = await client.threadsRequest();
    assert.deepStrictEqual(threads.body.threads.map((t) => t.name), ['PLCINIT', 'PLC1', 'PLCMAIN']);
    const plc1 = threads.body.threads[1].id;
    let frame = await top(plc1);
    const vars = await client.variablesRequest({ variablesReference: await globalsOf(frame.id) });
    const byName = Object.fromEntries(vars.body.variables.map((v) => [v.name, v.value]));
    assert.strictEqual(byName.N, '1');
    assert.strictEqual(byName.DIV, '1');

    // Into TWICE, out of it, and over the last line of the run.
    const step = async (request, line) =>
      Promise.all([client[request]({ threadId: plc1 }), client.assertStoppedLocation('step', { path: st, line })]);
    await step('stepInRequest', 8);
    const trace = await client.stackTraceRequest({ threadId: plc1 });
    assert.deepStrictEqual(trace.body.stackFrames.map((f) => [f.name, f.line]), [['TWICE', 8], ['PLC1', 12]]);
    await step('stepOutRequest', 13);
    frame = await top(plc1);
    assert.strictEqual(await evaluate('D', frame.id), '2');

    // A breakpoint on the third hit: PLC1's runs 2, 3 and 4 reach line 13; run 4 stops.
    await client.setBreakpointsRequest({ source: { path: st }, breakpoints: [] });
    await client.setBreakpointsRequest({ source: { path: st }, breakpoints: [{ line: 13, hitCondition: '3' }] });
    await Promise.all([client.continueRequest({ threadId: plc1 }), client.assertStoppedLocation('breakpoint', { path: st, line: 13 })]);
    frame = await top(plc1);
    assert.strictEqual(await evaluate('N', frame.id), '4');
    assert.strictEqual(await evaluate('Q', frame.id), '7');  // run 3's D + 1

    // Set N and see the next run use it: N 101, D 202 at line 13 of run 5.
    const set = await client.setVariableRequest({ variablesReference: await globalsOf(frame.id), name: 'N', value: '100' });
    assert.strictEqual(set.body.value, '100');
    await client.setBreakpointsRequest({ source: { path: st }, breakpoints: [{ line: 13 }] });
    await Promise.all([client.continueRequest({ threadId: plc1 }), client.assertStoppedLocation('breakpoint', { path: st, line: 13 })]);
    frame = await top(plc1);
    assert.strictEqual(await evaluate('D', frame.id), '202');
    assert.strictEqual(await evaluate('D / 2 - N', frame.id), '0');

    // DIV set to 0: PLCMAIN's division stops on the run-time error.
    await client.setBreakpointsRequest({ source: { path: st }, breakpoints: [] });
    await client.setVariableRequest({ variablesReference: await globalsOf(frame.id), name: 'DIV', value: '0' });
    await client.setExceptionBreakpointsRequest({ filters: ['error'] });
    const [, stopped] = await Promise.all([client.continueRequest({ threadId: plc1 }), client.waitForEvent('stopped')]);
    assert.strictEqual(stopped.body.reason, 'exception');
    assert.match(stopped.body.description, /division by zero/i);
    const failed = await top(stopped.body.threadId);
    assert.deepStrictEqual([failed.name, failed.line], ['PLCMAIN', 16]);

    // Continue to the end: the drive stops the PLC on F31, exit code 1.
    const [, exited] = await Promise.all([
      client.continueRequest({ threadId: plc1 }),
      client.waitForEvent('exited'),
      client.waitForEvent('terminated'),
    ]);
    assert.strictEqual(exited.body.exitCode, 1);
  } finally {
    await client.stop();
  }
});

// PUP through its stored form: `uprog build` writes X.cup and its debug map X.cup.json, `uprog sim
// --program X.cup` reads both, and an attached debugger stops at the PUP line while the command
// line reports the thread at its breakpoint (AProgStatus 4).
test('attach to a PUP program that uprog sim runs from its .cup', async () => {
  const { execFileSync } = require('node:child_process');
  const fs = require('node:fs');
  const os = require('node:os');
  const pup = path.resolve(__dirname, 'programs', 'two_threads.pup');
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'uprog-pup-'));
  const cup = path.join(dir, 'two_threads.cup');
  execFileSync(uprog, ['build', pup, '-o', cup]);
  assert.ok(fs.existsSync(cup + '.json'), 'no debug map beside the .cup');
  const { sim, line, dap } = await startSim(cup);
  const host = await commandLine(line);
  const client = newClient();
  try {
    assert.strictEqual(await host.ask('AProgRun[1],1'), ';');
    await client.start();
    await client.initializeRequest();
    await Promise.all([client.attachRequest({ host: '127.0.0.1', port: dap }), client.waitForEvent('initialized')]);
    const set = await client.setBreakpointsRequest({ source: { path: pup }, breakpoints: [{ line: 12 }] });
    assert.strictEqual(set.body.breakpoints[0].verified, true);
    const [, stopped] = await Promise.all([client.configurationDoneRequest(), client.waitForEvent('stopped')]);
    assert.strictEqual(stopped.body.reason, 'breakpoint');
    const trace = await client.stackTraceRequest({ threadId: stopped.body.threadId });
    assert.deepStrictEqual(trace.body.stackFrames.map((f) => [f.name, f.line]), [['task 2', 12]]);
    assert.strictEqual(await host.ask('AProgStatus[2]'), '4;');
    assert.strictEqual(await host.ask('AProgStatus[1]'), '3;');
  } finally {
    await client.stop();
    host.close();
    sim.kill();
    fs.rmSync(dir, { recursive: true, force: true });
  }
});
