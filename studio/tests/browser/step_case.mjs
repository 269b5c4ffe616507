// Step in, over and out from the toolbar, on a program of each dialect with a call: a gutter
// breakpoint on the call stops there (the paused line highlighted); step in stands in the
// callee's first line with its arguments in `variables` and two frames in `call-stack`; step out
// is back in the caller, on the statement after the call (docs/debugging.md: "out: back in main at
// line 12"); step over goes on to the caller's next statement.
import { clickGutter, expectVariable, lineOf, openStudio, shots, stoppedFrame }
  from "./helpers.mjs";
import { join } from "node:path";

// The paused line's text once the program stands on `line`.
async function pausedOn(page, c, line) {
  const frame = await stoppedFrame(page);
  if (frame.line !== line) throw new Error(`${c.dialect}: stopped at ${frame.line}, not ${line}`);
  await page.waitForFunction((text) => document.querySelector(".cm-paused-line")?.textContent
    .includes(text), c.lines[line], { timeout: 10000 });
  return frame;
}

async function step(page, testid) {
  await page.click(`[data-testid=${testid}]`);
}

// `c`: { dialect, file, call (the call's line text), callee (its first line's text), argument:
// [name, value] in the callee, out and after: [text, nth] of the caller's lines that step out
// and then step over reach }.
export async function stepCase(browser, c) {
  const { page, errors, close } = await openStudio(browser, c.file);
  const call = lineOf(c.file, c.call), callee = lineOf(c.file, c.callee);
  c.lines = { [call]: c.call.trim(), [callee]: c.callee.trim() };
  let where = "the breakpoint on the call";  // what the case waits for, named in its error
  try {
    await clickGutter(page, call);
    await page.selectOption("[data-testid=speed]", "5");
    await page.click("[data-testid=run]");  // Run builds the editor's text first
    where = "the stop at the call's breakpoint";
    await pausedOn(page, c, call);
    where = "the breakpoint's removal";
    await clickGutter(page, call);  // off: the steps are the toolbar's
    where = "the stop after step in";
    await step(page, "debug-step-in");
    const inside = await pausedOn(page, c, callee);
    if (inside.depth < 2) throw new Error(`${c.dialect}: step in left ${inside.depth} frame`);
    await expectVariable(page, c.argument[0], c.argument[1]);
    await page.screenshot({ path: join(shots, `${c.dialect}_6_stepped_in.png`) });
    // Without `out` (PUP: see docs/studio.md), step over stays in the callee.
    let back = inside;
    if (c.out) {
      where = "the stop after step out";
      await step(page, "debug-step-out");
      back = await stoppedFrame(page, 20000);
      const out = lineOf(c.file, ...c.out);
      if (back.depth !== inside.depth - 1 || back.line !== out) {
        throw new Error(`${c.dialect}: step out stopped at ${back.line} (${back.depth} frames)`);
      }
    }
    where = "the stop after step over";
    await step(page, "debug-step-over");
    const on = await stoppedFrame(page);
    const after = lineOf(c.file, ...c.after);
    if (on.depth !== back.depth || on.line !== after) {
      throw new Error(`${c.dialect}: step over stopped at ${on.line} (${on.depth} frames)`);
    }
    where = "the run after continue";
    await page.click("[data-testid=debug-continue]");
    await page.waitForFunction(() => !document.querySelector(".cm-paused-line"), null,
      { timeout: 10000 });
    if (errors.length) throw new Error(`page errors: ${errors.join("; ")}`);
  } catch (e) {
    await page.screenshot({ path: join(shots, `${c.dialect}_steps_failed.png`) });
    const output = await page.locator("[data-testid=output]").textContent();
    throw new Error(`waiting for ${where}: ${e.message}\noutput panel:\n${output}`);
  } finally {
    await close();
  }
}
