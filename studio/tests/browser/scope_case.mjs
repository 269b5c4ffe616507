// The scope on Gold's first move: channels picked (signals and a program global), a rising
// trigger with pre-trigger, pause, cursors, CSV and PNG export (the CSV holds every sample of the
// window, the plot only a decimated few); then 8 channels at x1 counted against the drive's time.
import { join } from "node:path";
import { download, expectText, openStudio, shots } from "./helpers.mjs";

const file = "examples/gold/first_move.ehl";
const kPeriodS = 50e-6;  // Gold's servo cycle (gold-drive.md: 50 us)
const kWindowS = 0.5, kPretrigger = 0.25, kLevel = 50000;  // the move goes 0 -> 100000 (PA)

async function setValue(page, testid, value) {
  await page.fill(`[data-testid=${testid}]`, String(value));
  await page.dispatchEvent(`[data-testid=${testid}]`, "change");
}

async function pickSignals(page) {
  await page.check("[data-testid=channel-velocity]");
  await page.waitForFunction(() => window.studio.scope.channels.map((c) => c.name).join() ===
    "position,velocity", null, { timeout: 10000 });
}

// A program's global is a channel once the program runs (its image is loaded): first_move.txt
// has moves = 1 once the move has settled.
async function pickAGlobal(page) {
  await page.fill("[data-testid=channel-add]", "moves");
  await page.press("[data-testid=channel-add]", "Enter");
  await page.waitForFunction(() => window.studio.scope.channels.map((c) => c.name).join() ===
    "position,velocity,moves", null, { timeout: 10000 });
  await page.waitForFunction(() => window.studio.scope.latest("moves") === 1, null,
    { timeout: 20000 });
}

// Rising through kLevel on position: the window starts kPretrigger of it before the crossing.
async function triggerCatchesTheMove(page) {
  await pickSignals(page);
  await page.selectOption("[data-testid=trigger-mode]", "rising");
  await page.selectOption("[data-testid=trigger-channel]", { label: "position" });
  await setValue(page, "trigger-level", kLevel);
  await setValue(page, "pretrigger", kPretrigger * 100);
  await setValue(page, "scope-window", kWindowS);
  await page.selectOption("[data-testid=speed]", "2");
  await page.click("[data-testid=run]");
  await expectText(page, "output", /program started/);
  // The window on display is the trigger's (free run drew others before).
  await page.waitForFunction((pre) => {
    const s = window.studio.scope;
    return s.triggerAt >= 0 && s.shown?.[0] === s.triggerAt - pre;
  }, Math.round(kWindowS / kPeriodS * kPretrigger), { timeout: 30000 });
}

// The CSV: a header, every servo cycle of the window (none skipped), the crossing where the
// pre-trigger puts it.
function checkCsv(text, shownPoints) {
  const rows = text.trim().split("\n");
  if (rows[0] !== "time_s,position,velocity") throw new Error(`CSV head: ${rows[0]}`);
  const samples = rows.slice(1).map((r) => r.split(",").map(Number));
  const expected = Math.round(kWindowS / kPeriodS);
  if (samples.length !== expected) throw new Error(`CSV: ${samples.length} samples`);
  for (let i = 1; i < samples.length; ++i) {
    if (Math.abs(samples[i][0] - samples[i - 1][0] - kPeriodS) > 1e-9) {
      throw new Error(`CSV: a gap at ${samples[i - 1][0]} s`);
    }
  }
  if (shownPoints >= samples.length) throw new Error("the plot is not decimated");
  const at = Math.round(expected * kPretrigger);
  if (!(samples[at - 1][1] < kLevel && samples[at][1] >= kLevel)) {
    throw new Error(`CSV: no rising crossing of ${kLevel} at sample ${at}`);
  }
}

async function pauseHoldsThePlot(page) {
  await page.click("[data-testid=scope-pause]");
  const held = await page.evaluate(() => window.studio.scope.plot.data[0].slice());
  await page.waitForTimeout(300);
  const still = await page.evaluate((h) => {
    const now = window.studio.scope.plot.data[0];
    return now.length === h.length && now.every((x, i) => x === h[i]);
  }, held);
  if (!still) throw new Error("the paused plot changed");
}

// Two clicks on the plot set cursors A and B; the box shows both and their distance.
async function cursors(page) {
  const over = await page.locator("[data-testid=scope] .u-over").boundingBox();
  await page.mouse.click(over.x + over.width * 0.2, over.y + over.height / 2);
  await page.mouse.click(over.x + over.width * 0.7, over.y + over.height / 2);
  await expectText(page, "cursors",
    /^A: t=[\d.]+ s position=.* \| B: t=[\d.]+ s .* \| Δt=0\.\d+ s$/);
}

// 8 channels at x1 for 1.5 s: every cycle between the first and the last sample arrived, in order,
// and the drive's time kept up with the wall clock.
async function eightChannelsAtFullRate(page) {
  await page.selectOption("[data-testid=trigger-mode]", "free");
  for (const name of ["position_error", "reference_position", "reference_velocity",
    "current_command", "active_current"]) {
    await page.check(`[data-testid=channel-${name}]`);
  }
  await page.waitForFunction(() => window.studio.scope.channels.length === 8);
  await page.selectOption("[data-testid=speed]", "1");
  await page.waitForTimeout(300);
  const look = () => page.evaluate(() => {
    const s = window.studio.scope;
    return { received: s.received, total: s.total, last: s.times[(s.total - 1) % s.capacity],
      wall: performance.now() / 1000 };
  });
  const a = await look();
  await page.waitForTimeout(1500);
  const b = await look();
  const spanS = b.last - a.last, wallS = b.wall - a.wall;
  const expected = Math.round(spanS / kPeriodS);
  if (b.received - a.received !== expected) {
    throw new Error(`8 channels: ${b.received - a.received} samples for ${spanS} s (${expected})`);
  }
  const gaps = await page.evaluate((period) => {
    const s = window.studio.scope;
    let gaps = 0;
    for (let i = s.oldest() + 1; i < s.total; ++i) {
      if (Math.abs(s.times[i % s.capacity] - s.times[(i - 1) % s.capacity] - period) > 1e-9) ++gaps;
    }
    return gaps;
  }, kPeriodS);
  if (gaps) throw new Error(`8 channels: ${gaps} gaps in the kept samples`);
  if (spanS < 0.8 * wallS) throw new Error(`8 channels at x1: ${spanS} s in ${wallS} s`);
  return { samples: expected, spanS, wallS };
}

export async function scopeCase(browser) {
  const { page, errors, close } = await openStudio(browser, file);
  let step = "";
  const named = (name, promise) => {
    step = name;
    return promise;
  };
  try {
    await named("triggerCatchesTheMove", triggerCatchesTheMove(page));
    await named("pauseHoldsThePlot", pauseHoldsThePlot(page));
    step = "export";
    const shownPoints = await page.evaluate(() => window.studio.scope.plot.data[0].length);
    checkCsv((await download(page, "export-csv")).toString("utf8"), shownPoints);
    const png = await download(page, "export-png");
    if (png.subarray(1, 4).toString() !== "PNG") throw new Error("PNG export is not a PNG");
    await named("cursors", cursors(page));
    await page.screenshot({ path: join(shots, "gold_7_scope.png") });
    await page.click("[data-testid=scope-pause]");  // resume
    await named("pickAGlobal", pickAGlobal(page));
    const rate = await named("eightChannelsAtFullRate", eightChannelsAtFullRate(page));
    if (errors.length) throw new Error(`page errors: ${errors.join("; ")}`);
    return rate;
  } catch (e) {
    await page.screenshot({ path: join(shots, "scope_failed.png") });
    throw new Error(`${step}: ${e.message}`);
  } finally {
    await close();
  }
}
