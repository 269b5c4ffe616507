// The studio in a real browser: playwright-core drives Debian's chromium headless against
// `uprog studio` on each dialect's example. The editor with the language server (a broken line's
// diagnostic, hover, completion, go to definition); build and run; the threads' status; the
// position moves in the scope; a gutter breakpoint (a condition, a hit count) stops the program,
// the call stack, variables and a watch show, a step changes the variable, continue; step in,
// out and over on a program with a call; the scope's channels, trigger, pause, cursors and export,
// 8 channels at the full rate; an input toggle runs Gold's AUTO_I2 (manual 2.14.8), a switch on
// the axis, fault injection. Screenshots go to SCREENSHOTS (the build folder).
// Environment: UPROG (the binary), CHROMIUM (optional path), SCREENSHOTS (a folder).
// Usage: node studio_browser_test.mjs [gold|pdl|pup|st|steps|scope|input]  (default: all)
// Exit 77 (ctest's skip) when there is no chromium.
import { existsSync, mkdirSync } from "node:fs";
import { join } from "node:path";
import { chromium } from "playwright-core";
import { clickGutter, expectText, lineOf, openStudio, shots, variableText }
  from "./browser/helpers.mjs";
import { languageServerSteps } from "./browser/editor_steps.mjs";
import { stepCase } from "./browser/step_case.mjs";
import { scopeCase } from "./browser/scope_case.mjs";

const browserPath = [process.env.CHROMIUM, "/usr/bin/chromium", "/usr/bin/chromium-browser"]
  .find((p) => p && existsSync(p));
if (!browserPath) {
  console.log("SKIP: no chromium (scripts/install-deps installs Debian's)");
  process.exit(77);
}
mkdirSync(shots, { recursive: true });

// Each dialect's example: its position signal's target (from the example and its transcript), the
// thread the program runs on (docs/debugging.md names them), and a line whose variable the
// breakpoint reads before and after a step. `read`: a variable's value at the stop; `step`: a
// variable the step over the line changes (to `after`, or just to another value); `condition`
// and `hits`: answered to the gutter's right-click prompts.
// `lsp`: a line to break; a hover over a drive command or keyword and the words its reference
// text has (the drive spec's or manual's meaning); a prefix whose completions include `labels`; a
// name's use and its declaration's line (the example's text).
const cases = [
  { dialect: "gold", file: "examples/gold/first_move.ehl", target: 100000,  // PA=100000
    thread: "program", breakAt: "moves = moves + 1", read: ["moves", "0"], step: ["moves", "1"],
    lsp: { broken: "moves = moves + 1",
      hover: { text: "UM = 5", word: "UM",
        shows: /unit mode.*1 current.*2 velocity.*5 position/is },  // gold-drive.md
      complete: { prefix: "mo", labels: ["moves", "MO"] },  // gold-drive.md: MO, motor enable
      definition: { text: "moves = moves + 1", name: "moves", declared: "int moves" } } },
  // The move ended in time (move_with_timeout.txt: result 1), so line 21 runs and sets t0.
  { dialect: "pdl", file: "examples/pdl/move_with_timeout.pdl", target: 10000,  // X_trg=10000
    thread: "task 1", breakAt: "t0=fclk-t0;", read: ["result", "1"], step: ["t0", null],
    lsp: { broken: "t0=fclk-t0;",
      hover: { text: "seton X_enable", word: "X_enable", shows: /servo on/i },  // pdl-drive.md
      complete: { prefix: "X_v", labels: ["X_vel", "X_vel_max"] },
      definition: { text: "t0=fclk-t0;", name: "t0", declared: "#long t0" } } },
  // Its third pass (a hit count of 3): Moves was 0, 1, 2 at the passes (point_to_point.txt).
  { dialect: "pup", file: "examples/pup/point_to_point.pup", target: 20000,  // FAR
    thread: "thread 1", breakAt: "Moves = Moves + 1", hits: "3", read: ["Moves", "2"],
    step: ["Moves", "3"],
    lsp: { broken: "Moves = Moves + 1",
      // akribis-drive.md: AMotorOn is Gold's MO, the motor enable
      hover: { text: "AMotorOn = 1", word: "AMotorOn", shows: /motor enable/i },
      complete: { prefix: "AMo", labels: ["AMotorOn", "AMotionMode"] },
      definition: { text: "Moves = Moves + 1", name: "Moves", declared: "#definevar Moves" } } },
  // A conditional breakpoint: the second round's (ROUNDS counts 3 rounds, move_sequence.st).
  { dialect: "st", file: "examples/st/move_sequence.st", target: 5000,  // ORDER 192 5000
    thread: "PLCMAIN", breakAt: "ROUNDS := ROUNDS + 1;", condition: "ROUNDS = 1",
    read: ["ROUNDS", "1"], step: ["ROUNDS", "2"],
    lsp: { broken: "ROUNDS := ROUNDS + 1;",
      // manual (003) "read value of PGEARO ... XREAD('PGEARO',MYPGEARO)"
      hover: { text: "XREAD('ACTIVE'", word: "XREAD", shows: /reads a drive parameter/i },
      complete: { prefix: "XR", labels: ["XREAD"] },
      definition: { text: "ROUNDS := ROUNDS + 1;", name: "ROUNDS", declared: "LONG STEP" } } },
];

// Step in, out and over on a program of each dialect with a call (step_case.mjs). The callee's
// argument: Gold's manual 2.5 calls myfunction(1, 2.5); pdl_calls.pdl's first inner(i) has i = 1;
// library_user.pup sets Target = 5000 before MOVE_TO; ST has no locals, STEP is 2 at WAITINPOS.
// PUP's step in stands on the AProgFunc line; its step out is left out (docs/studio.md).
const stepCases = [
  { dialect: "gold", file: "examples/gold/2_05_user_functions.ehl", call: "myfunction(1, 2.5)",
    callee: "UF[1] = arg1 * arg2", argument: ["arg2", "2.5"], out: ["x = myfunction1()"],
    after: ["[x, y] = myfunction2(3, 4)"] },
  // The loop's end jumps back: step over from inner's call reaches i=i+1 again.
  { dialect: "pdl", file: "tests/transcripts/debug/programs/pdl_calls.pdl", call: "  inner(i);",
    callee: "  n=n+a;", argument: ["a", "1"], out: ["end;", 3], after: ["  i=i+1;"] },
  { dialect: "pup", file: "examples/pup/library_user.pup", call: "AProgFuncCall, MOVE_TO",
    callee: "AProgFunc[MOVE_TO]", argument: ["Target", "5000"], out: null,
    after: ["AAbsTrgt = Target"] },
  // ATTARGET is 0 at once (the move just began), so step over passes the IF to the next STEP test.
  { dialect: "st", file: "examples/st/move_sequence.st", call: "FUNCTION (WAITINPOS);",
    callee: "XREAD('INPOS', ATTARGET);", argument: ["STEP", "2"], out: ["IF ATTARGET THEN"],
    after: ["IF STEP = 3 THEN"] },
];

async function runCase(browser, c) {
  const { page, errors, close } = await openStudio(browser, c.file);
  const shot = (step) => page.screenshot({ path: join(shots, `${c.dialect}_${step}.png`) });
  try {
    await languageServerSteps(page, c, shot);

    // A breakpoint on the line (a condition or hit count by right click), then run at x5: Run
    // builds and downloads the editor's text first.
    const line = lineOf(c.file, c.breakAt);
    const special = c.condition || c.hits;
    await clickGutter(page, line, special ? [c.condition ?? "", c.hits ?? ""] : null);
    await page.locator(".cm-breakpoint-gutter .bp:visible").waitFor();
    await page.selectOption("[data-testid=speed]", "5");
    await page.click("[data-testid=run]");
    await expectText(page, "output", /build: downloaded\nprogram started/);

    // It stops there: the paused line, the call stack, the thread's status, the variable; the
    // position has moved.
    await page.locator("[data-testid=call-stack] li").first().waitFor({ timeout: 20000 });
    await page.locator(".cm-paused-line").waitFor();
    await expectText(page, "threads", new RegExp(`${c.thread}at breakpoint`));
    await shot("2_stopped");
    const moved = await page.evaluate((target) => {
      const s = window.studio.scope;
      let max = -Infinity;
      for (let i = s.oldest(); i < s.total; ++i) max = Math.max(max, s.at(0, i));
      return max >= 0.99 * target;
    }, c.target);
    if (!moved) throw new Error(`${c.dialect}: the position never reached ${c.target}`);
    await expectText(page, "scope", /position = -?\d/);
    await page.locator("[data-testid=variables] .variable").first().waitFor();
    const text = await variableText(page, c.read[0]);
    if (text !== `${c.read[0]} = ${c.read[1]}`) throw new Error(`${c.dialect}: read ${text}`);
    // A watch of the same variable evaluates to the same value in the stopped frame.
    await page.fill("[data-testid=watch-input]", c.read[0]);
    await page.press("[data-testid=watch-input]", "Enter");
    await expectText(page, "watches", new RegExp(`^${c.read[0]} = ${c.read[1]}$`));
    const before = await variableText(page, c.step[0]);
    await page.click("[data-testid=debug-step-over]");
    await page.locator("[data-testid=call-stack] li").first().waitFor({ timeout: 10000 });
    const [name, after] = c.step;
    await page.waitForFunction(([n, a, b]) => {
      const t = document.querySelector(`[data-testid=variables] .variable[data-name="${n}"]`)
        ?.textContent;
      return a != null ? t === `${n} = ${a}` : t != null && t !== b;
    }, [name, after, before], { timeout: 10000 });
    await shot("3_stepped");
    // Continue without the breakpoint: the program goes on.
    await clickGutter(page, line);
    await page.click("[data-testid=debug-continue]");
    await page.waitForFunction(() => !document.querySelector(".cm-paused-line"), null,
      { timeout: 10000 });
    await shot("4_continued");
    if (errors.length) throw new Error(`${c.dialect}: page errors: ${errors.join("; ")}`);
  } catch (e) {
    await shot("failed");
    const output = await page.locator("[data-testid=output]").textContent();
    throw new Error(`${e.message}\noutput panel:\n${output}`);
  } finally {
    await close();
  }
}

// Manual 2.14.8: input 2 on and off runs AUTO_I2 (UI[1]=9000) and main moves to 9000. A switch on
// input 6 (general purpose by default, no auto-routine in the program) over [8500, 9500] is high
// once the axis stands at 9000.
async function inputCase(browser) {
  const { page, close } = await openStudio(browser, "examples/gold/2_14_auto_inputs.ehl");
  try {
    await page.selectOption("[data-testid=speed]", "5");
    await page.selectOption("[data-testid=switch-input]", "6");
    await page.fill("[data-testid=switch-from]", "8500");
    await page.fill("[data-testid=switch-to]", "9500");
    await page.click("[data-testid=switch-place]");
    await page.click("[data-testid=build]");
    await expectText(page, "output", /build: downloaded/);
    await page.click("[data-testid=run]");
    await expectText(page, "output", /program started/);
    if (await page.isChecked("[data-testid=input-6]")) throw new Error("input 6 high at 0");
    await page.click("[data-testid=input-2]");
    await page.waitForTimeout(100);
    await page.click("[data-testid=input-2]");
    await page.waitForFunction(() => Math.abs(window.studio.scope.latest("position") - 9000) <= 2,
      null, { timeout: 10000 });
    await page.waitForFunction(() => document.querySelector("[data-testid=input-6]").checked,
      null, { timeout: 5000 });
    // The terminal reads it too, as `uprog term` would.
    await page.click("[data-testid=terminal]");
    await page.keyboard.type("UI[1]\n");
    await expectText(page, "terminal", /> UI\[1\]\s*0/);
    // A fault injected latches its MF bit (drive/faults.h: overcurrent is 0x8).
    await page.selectOption("[data-testid=fault-name]", "overcurrent");
    await page.click("[data-testid=fault-inject]");
    await expectText(page, "motor-fault", /MF = 0x[0-9a-f]*8$/);
    await page.screenshot({ path: join(shots, "gold_5_input.png") });
  } finally {
    await close();
  }
}

const browser = await chromium.launch({ executablePath: browserPath, headless: true,
  args: ["--no-sandbox"] });
let failed = false;
const only = process.argv[2];
async function check(name, run) {
  const t0 = Date.now();
  try {
    const note = await run();
    const seconds = ((Date.now() - t0) / 1000).toFixed(1);
    console.log(`ok ${name} (${seconds} s)${note ? " " + JSON.stringify(note) : ""}`);
  } catch (e) {
    failed = true;
    console.log(`FAILED ${name}: ${e.message}`);
  }
}
// The parts are independent (a studio each): STUDIO_BROWSER_JOBS of them at once (default 2),
// since most of a part's time is waiting for the drive's time to pass.
const parts = [];
for (const c of cases) {
  if (!only || only === c.dialect) parts.push([c.dialect, () => runCase(browser, c)]);
}
for (const c of stepCases) {
  if (!only || only === "steps") parts.push([`${c.dialect} steps`, () => stepCase(browser, c)]);
}
if (!only || only === "scope") parts.push(["gold scope", () => scopeCase(browser)]);
if (!only || only === "input") parts.push(["gold input", () => inputCase(browser)]);
const t0 = Date.now();
const jobs = Math.max(1, Number(process.env.STUDIO_BROWSER_JOBS ?? 2));
const worker = async () => {
  for (let part = parts.shift(); part; part = parts.shift()) await check(...part);
};
await Promise.all(Array.from({ length: jobs }, worker));
console.log(`${((Date.now() - t0) / 1000).toFixed(1)} s in all`);
await browser.close();
process.exit(failed ? 1 : 0);
