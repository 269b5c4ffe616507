// The studio in a real browser: playwright-core drives Debian's chromium headless against
// `uprog studio` on each dialect's example. A broken line shows a diagnostic; build and run; the
// position moves in the scope; a breakpoint stops the program, the call stack and a variable
// show, a step changes the variable, continue lets it end; an input toggle runs Gold's
// AUTO_I2 (manual 2.14.8). Screenshots go to SCREENSHOTS (the build folder).
// Environment: UPROG (the binary), CHROMIUM (optional path), SCREENSHOTS (a folder).
// Exit 77 (ctest's skip) when there is no chromium.
import { spawn } from "node:child_process";
import { existsSync, mkdirSync, readFileSync } from "node:fs";
import { join, dirname } from "node:path";
import { fileURLToPath } from "node:url";
import { chromium } from "playwright-core";

const root = join(dirname(fileURLToPath(import.meta.url)), "../..");
const uprog = process.env.UPROG ?? join(root, "build/bin/uprog");
const shots = process.env.SCREENSHOTS ?? join(root, "build/studio-screenshots");
const browserPath = [process.env.CHROMIUM, "/usr/bin/chromium", "/usr/bin/chromium-browser"]
  .find((p) => p && existsSync(p));
if (!browserPath) {
  console.log("SKIP: no chromium (scripts/install-deps installs Debian's)");
  process.exit(77);
}
mkdirSync(shots, { recursive: true });

// Each dialect's example, its position signal's target (from the example and its transcript),
// and a line whose variable the breakpoint reads before and after a step.
// `read`: a variable's value at the stop; `step`: a variable the step over the line changes (to
// `after`, or just to another value).
const cases = [
  { dialect: "gold", file: "examples/gold/first_move.ehl", target: 100000,  // PA=100000
    breakAt: "moves = moves + 1", read: ["moves", "0"], step: ["moves", "1"] },
  // The move ended in time (move_with_timeout.txt: result 1), so line 21 runs and sets t0.
  { dialect: "pdl", file: "examples/pdl/move_with_timeout.pdl", target: 10000,  // X_trg=10000
    breakAt: "t0=fclk-t0;", read: ["result", "1"], step: ["t0", null] },
  { dialect: "pup", file: "examples/pup/point_to_point.pup", target: 20000,  // FAR
    breakAt: "Moves = Moves + 1", read: null, step: null },
  // A conditional breakpoint: the second round's (ROUNDS counts 3 rounds, move_sequence.st).
  { dialect: "st", file: "examples/st/move_sequence.st", target: 5000,  // ORDER 192 5000
    breakAt: "ROUNDS := ROUNDS + 1;", condition: "ROUNDS = 1", read: ["ROUNDS", "1"],
    step: ["ROUNDS", "2"] },
];

function startStudio(file) {
  const child = spawn(uprog, ["studio", join(root, file), "--listen", "127.0.0.1:0"],
    { stdio: ["ignore", "pipe", "inherit"] });
  return new Promise((resolve, reject) => {
    let text = "";
    child.stdout.on("data", (d) => {
      text += d;
      const m = /studio on (http:\/\/\S+)/.exec(text);
      if (m) resolve({ child, url: m[1] });
    });
    child.on("exit", (code) => reject(new Error(`uprog studio exited with ${code}`)));
  });
}

async function expectText(page, testid, pattern, timeout = 10000) {
  await page.waitForFunction(([id, source]) => new RegExp(source).test(
    document.querySelector(`[data-testid=${id}]`)?.textContent ?? ""), [testid, pattern.source],
  { timeout });
}

// The line number of the first line that contains `text`.
function lineOf(file, text) {
  return readFileSync(join(root, file), "utf8").split("\n").findIndex((l) => l.includes(text)) + 1;
}

// The cursor at the end of a line, scrolled into view (the editor draws only what is in view).
async function goToLineEnd(page, line) {
  await page.evaluate((n) => {
    const view = window.studio.editor;
    view.dispatch({ selection: { anchor: view.state.doc.line(n).to }, scrollIntoView: true });
    view.focus();
  }, line);
}

// A right click asks for the condition and the hit count (two prompts).
async function clickGutter(page, line, answers) {
  await goToLineEnd(page, line);
  const number = page.locator(".cm-lineNumbers .cm-gutterElement", { hasText: new RegExp(`^${line}$`) });
  const box = await number.boundingBox();
  const gutter = await page.locator(".cm-breakpoint-gutter").boundingBox();
  if (!answers) return page.mouse.click(gutter.x + gutter.width / 2, box.y + box.height / 2);
  const replies = [...answers];
  const reply = (dialog) => dialog.accept(replies.shift() ?? "");
  page.on("dialog", reply);
  await page.mouse.click(gutter.x + gutter.width / 2, box.y + box.height / 2, { button: "right" });
  await page.waitForFunction(() => document.querySelector(".cm-breakpoint-gutter .bp-conditional"));
  page.off("dialog", reply);
}

async function variableText(page, name) {
  return page.locator(`[data-testid=variables] .variable[data-name="${name}"]`).first().textContent();
}

async function runCase(browser, c) {
  const { child, url } = await startStudio(c.file);
  const page = await browser.newPage({ viewport: { width: 1400, height: 900 } });
  const errors = [];
  page.on("pageerror", (e) => errors.push(e.message));
  const shot = (step) => page.screenshot({ path: join(shots, `${c.dialect}_${step}.png`) });
  try {
    await page.goto(url);
    await page.waitForFunction(() => window.studio?.ready);
    await page.locator("[data-testid=editor] .cm-content").waitFor();

    // A broken line: the language server's diagnostic shows; undone, it goes.
    const line = lineOf(c.file, c.breakAt);
    await goToLineEnd(page, line);
    await page.keyboard.type(" )(");
    await page.locator("[data-testid=diagnostics] li").first().waitFor({ timeout: 10000 });
    await shot("1_diagnostic");
    for (let i = 0; i < 3; ++i) await page.keyboard.press("Backspace");  // not undo: a slow
    // machine's typing may fall into several undo groups
    await page.waitForFunction(() => !document.querySelector("[data-testid=diagnostics] li"),
      null, { timeout: 10000 });

    // A breakpoint on the line, then build and run at x2.
    await clickGutter(page, line, c.condition ? [c.condition, ""] : null);
    await page.locator(".cm-breakpoint-gutter .bp:visible").waitFor();
    await page.selectOption("[data-testid=speed]", "2");
    await page.click("[data-testid=build]");
    await expectText(page, "output", /build: downloaded/);
    await page.click("[data-testid=run]");
    await expectText(page, "output", /program started/);

    // It stops there: the paused line, the call stack, the variable; the position has moved.
    await page.locator("[data-testid=call-stack] li").first().waitFor({ timeout: 20000 });
    await page.locator(".cm-paused-line").waitFor();
    await shot("2_stopped");
    const moved = await page.evaluate((target) => {
      const s = window.studio.scope;
      let max = -Infinity;
      for (let i = s.oldest(); i < s.total; ++i) max = Math.max(max, s.at(0, i));
      return max >= 0.99 * target;
    }, c.target);
    if (!moved) throw new Error(`${c.dialect}: the position never reached ${c.target} in the scope`);
    await expectText(page, "scope", /position = -?\d/);
    await page.locator("[data-testid=variables] .variable").first().waitFor();
    if (c.read) {
      const text = await variableText(page, c.read[0]);
      if (text !== `${c.read[0]} = ${c.read[1]}`) throw new Error(`${c.dialect}: read ${text}`);
    }
    if (c.read) {
      // A watch of the same variable evaluates to the same value in the stopped frame.
      await page.fill("[data-testid=watch-input]", c.read[0]);
      await page.press("[data-testid=watch-input]", "Enter");
      await expectText(page, "watches", new RegExp(`^${c.read[0]} = ${c.read[1]}$`));
    }
    const before = c.step ? await variableText(page, c.step[0]) : null;
    await page.click("[data-testid=debug-step-over]");
    await page.locator("[data-testid=call-stack] li").first().waitFor({ timeout: 10000 });
    if (c.step) {
      const [name, after] = c.step;
      await page.waitForFunction(([n, a, b]) => {
        const t = document.querySelector(`[data-testid=variables] .variable[data-name="${n}"]`)?.textContent;
        return a != null ? t === `${n} = ${a}` : t != null && t !== b;
      }, [name, after, before], { timeout: 10000 });
    }
    await shot("3_stepped");
    // Continue without the breakpoint: the program goes on.
    await clickGutter(page, line);
    await page.click("[data-testid=debug-continue]");
    await page.waitForFunction(() => !document.querySelector(".cm-paused-line"), null, { timeout: 10000 });
    await shot("4_continued");
    if (errors.length) throw new Error(`${c.dialect}: page errors: ${errors.join("; ")}`);
  } catch (e) {
    await shot("failed");
    const output = await page.locator("[data-testid=output]").textContent();
    throw new Error(`${e.message}\noutput panel:\n${output}`);
  } finally {
    await page.close();
    child.kill("SIGTERM");
  }
}

// Manual 2.14.8: input 2 on and off runs AUTO_I2 (UI[1]=9000) and main moves to 9000.
async function inputCase(browser) {
  const { child, url } = await startStudio("examples/gold/2_14_auto_inputs.ehl");
  const page = await browser.newPage({ viewport: { width: 1400, height: 900 } });
  try {
    await page.goto(url);
    await page.waitForFunction(() => window.studio?.ready);
    await page.selectOption("[data-testid=speed]", "5");
    await page.click("[data-testid=build]");
    await expectText(page, "output", /build: downloaded/);
    await page.click("[data-testid=run]");
    await expectText(page, "output", /program started/);
    await page.click("[data-testid=input-2]");
    await page.waitForTimeout(100);
    await page.click("[data-testid=input-2]");
    await page.waitForFunction(() => Math.abs(window.studio.scope.latest("position") - 9000) <= 2,
      null, { timeout: 10000 });
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
    await page.close();
    child.kill("SIGTERM");
  }
}

const browser = await chromium.launch({ executablePath: browserPath, headless: true,
  args: ["--no-sandbox"] });
let failed = false;
const only = process.argv[2];
for (const c of cases) {
  if (only && c.dialect !== only) continue;
  const t0 = Date.now();
  try {
    await runCase(browser, c);
    console.log(`ok ${c.dialect} (${((Date.now() - t0) / 1000).toFixed(1)} s)`);
  } catch (e) {
    failed = true;
    console.log(`FAILED ${c.dialect}: ${e.message}`);
  }
}
if (!only || only === "input") {
  try {
    await inputCase(browser);
    console.log("ok gold input");
  } catch (e) {
    failed = true;
    console.log(`FAILED gold input: ${e.message}`);
  }
}
await browser.close();
process.exit(failed ? 1 : 0);
