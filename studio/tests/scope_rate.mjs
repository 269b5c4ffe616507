// Measures the live scope in a real browser: 8 channels of Gold's first move at a speed (default
// x10) for 3 s of wall time; prints the samples received, the drive time they span and the samples
// that span should hold (every servo cycle). docs/studio.md quotes its figures.
// Usage: node studio/tests/scope_rate.mjs [SPEED]   (UPROG, CHROMIUM as for the browser test)
import { spawn } from "node:child_process";
import { join, dirname } from "node:path";
import { fileURLToPath } from "node:url";
import { chromium } from "playwright-core";

const root = join(dirname(fileURLToPath(import.meta.url)), "../..");
const uprog = process.env.UPROG ?? join(root, "build/bin/uprog");
const speed = process.argv[2] ?? "10";
const child = spawn(uprog, ["studio", join(root, "examples/gold/first_move.ehl"), "--listen",
  "127.0.0.1:0"], { stdio: ["ignore", "pipe", "inherit"] });
const url = await new Promise((resolve) => child.stdout.on("data", (d) => {
  const m = /studio on (\S+)/.exec(String(d));
  if (m) resolve(m[1]);
}));
const browser = await chromium.launch({ executablePath: process.env.CHROMIUM ?? "/usr/bin/chromium",
  args: ["--no-sandbox"] });
const page = await browser.newPage();
await page.goto(url);
await page.waitForFunction(() => window.studio?.ready);
await page.evaluate(() => window.studio.drive.send({ op: "scope",
  channels: ["PX", "VX", "PE", "IQ", "MS", "DV[1]", "DV[2]", "DV[3]"] }));
await page.waitForFunction(() => window.studio.scope.channels.length === 8);
await page.selectOption("[data-testid=speed]", speed);
await page.waitForTimeout(300);
const look = () => page.evaluate(() => {
  const s = window.studio.scope;
  return { n: s.received, t: s.times[(s.total - 1) % s.capacity], period: s.periodUs };
});
const a = await look();
await page.waitForTimeout(3000);
const b = await look();
console.log(JSON.stringify({ speed, wall_s: 3, samples: b.n - a.n, drive_s: b.t - a.t,
  expected: Math.round((b.t - a.t) * 1e6 / b.period) }));
await browser.close();
child.kill();
