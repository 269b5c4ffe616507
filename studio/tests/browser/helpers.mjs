// What the browser test's steps share: `uprog studio` on a file, a page on it, waiting for a
// panel's text, the editor's lines and cursor, gutter clicks, the variables panel, downloads.
import { spawn } from "node:child_process";
import { readFileSync } from "node:fs";
import { join, dirname } from "node:path";
import { fileURLToPath } from "node:url";

export const root = join(dirname(fileURLToPath(import.meta.url)), "../../..");
export const uprog = process.env.UPROG ?? join(root, "build/bin/uprog");
export const shots = process.env.SCREENSHOTS ?? join(root, "build/studio-screenshots");

// `uprog studio FILE` on a free loopback port: the child and the page's address.
export function startStudio(file) {
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

// The studio on `file` in a new page, ready (its editor drawn). `close()` ends both; `errors`
// collects the page's uncaught errors.
export async function openStudio(browser, file) {
  const { child, url } = await startStudio(file);
  const page = await browser.newPage({ viewport: { width: 1400, height: 900 } });
  const errors = [];
  page.on("pageerror", (e) => errors.push(e.message));
  const close = async () => {
    await page.close();
    child.kill("SIGTERM");
  };
  try {
    await page.goto(url);
    await page.waitForFunction(() => window.studio?.ready);
    await page.locator("[data-testid=editor] .cm-content").waitFor();
  } catch (e) {
    await close();
    throw e;
  }
  return { page, errors, close };
}

export async function expectText(page, testid, pattern, timeout = 10000) {
  await page.waitForFunction(([id, source, flags]) => new RegExp(source, flags).test(
    document.querySelector(`[data-testid=${id}]`)?.textContent ?? ""),
  [testid, pattern.source, pattern.flags], { timeout });
}

// The line number of the `nth` (1st by default) line of `file` that contains `text`.
export function lineOf(file, text, nth = 1) {
  const lines = readFileSync(join(root, file), "utf8").split("\n");
  for (let i = 0, seen = 0; i < lines.length; ++i) {
    if (lines[i].includes(text) && ++seen === nth) return i + 1;
  }
  throw new Error(`${file} has no line ${nth} with ${text}`);
}

// The cursor at the end of a line, scrolled into view (the editor draws only what is in view).
export async function goToLineEnd(page, line) {
  await page.evaluate((n) => {
    const view = window.studio.editor;
    view.dispatch({ selection: { anchor: view.state.doc.line(n).to }, scrollIntoView: true });
    view.focus();
  }, line);
}

// The line the editor's cursor is on.
export function cursorLine(page) {
  return page.evaluate(() => {
    const view = window.studio.editor;
    return view.state.doc.lineAt(view.state.selection.main.head).number;
  });
}

// The screen box of the first `word` on line `line` (scrolled into view first).
export async function wordBox(page, line, word) {
  return page.evaluate(([n, w]) => {
    const view = window.studio.editor;
    const l = view.state.doc.line(n);
    const at = l.from + l.text.indexOf(w);
    view.dispatch({ selection: { anchor: at }, scrollIntoView: true });
    view.focus();
    view.requestMeasure();
    const a = view.coordsAtPos(at), b = view.coordsAtPos(at + w.length);
    return { x: (a.left + b.left) / 2, y: (a.top + a.bottom) / 2 };
  }, [line, word]);
}

// A click in the breakpoint gutter of `line`; with `answers`, a right click that answers the
// condition and hit count prompts. It returns once the editor holds the change: the line's
// breakpoint toggled (or, with answers, made conditional). The scroll that brings the line into
// view lands at the editor's next measure, so a click at a box read before it may miss the
// line: then the box is read again and the click repeated (three tries).
export async function clickGutter(page, line, answers) {
  const lines = () => page.evaluate(() => window.studio.debug.breakpoints().map((b) => b.line));
  const before = await lines();
  for (let attempt = 1; ; ++attempt) {
    await goToLineEnd(page, line);
    await page.evaluate(() => new Promise((done) => requestAnimationFrame(() => done())));
    const number = page.locator(".cm-lineNumbers .cm-gutterElement",
      { hasText: new RegExp(`^${line}$`) });
    const box = await number.boundingBox();
    const gutter = await page.locator(".cm-breakpoint-gutter").boundingBox();
    const x = gutter.x + gutter.width / 2, y = box.y + box.height / 2;
    if (!answers) {
      await page.mouse.click(x, y);
    } else {
      const replies = [...answers];
      const reply = (dialog) => dialog.accept(replies.shift() ?? "");
      page.on("dialog", reply);
      await page.mouse.click(x, y, { button: "right" });
      await page.waitForFunction(() => document.querySelector(".cm-breakpoint-gutter .bp-conditional"),
        null, { timeout: 2000 }).catch(() => {});
      page.off("dialog", reply);
    }
    if (answers && await page.locator(".cm-breakpoint-gutter .bp-conditional").count()) return;
    const after = await lines();
    const toggled = after.filter((n) => !before.includes(n))
      .concat(before.filter((n) => !after.includes(n)));
    if (!answers && toggled.length === 1 && toggled[0] === line) return;
    if (toggled.length) throw new Error(`the gutter click for line ${line} toggled ${toggled}`);
    if (attempt === 3) throw new Error(`the gutter click on line ${line} did not take (3 tries)`);
  }
}

export function variableText(page, name) {
  return page.locator(`[data-testid=variables] .variable[data-name="${name}"]`).first()
    .textContent();
}

// Waits until the variables panel shows `name = value`.
export async function expectVariable(page, name, value, timeout = 10000) {
  await page.waitForFunction(([n, v]) => document.querySelector(
    `[data-testid=variables] .variable[data-name="${n}"]`)?.textContent === `${n} = ${v}`,
  [name, value], { timeout });
}

// The top frame of the call stack once the program stands still: { name, line, depth }.
export async function stoppedFrame(page, timeout = 10000) {
  await page.locator("[data-testid=call-stack] li").first().waitFor({ timeout });
  const frames = await page.locator("[data-testid=call-stack] li").allTextContents();
  const m = /^(.*) — (?:line |.*:)(\d+)$/.exec(frames[0]);
  return { name: m[1], line: Number(m[2]), depth: frames.length };
}

// Clicks `testid` and returns what the browser downloads, as a Buffer.
export async function download(page, testid) {
  const [file] = await Promise.all([page.waitForEvent("download"),
    page.click(`[data-testid=${testid}]`)]);
  const stream = await file.createReadStream();
  const chunks = [];
  for await (const chunk of stream) chunks.push(chunk);
  return Buffer.concat(chunks);
}
