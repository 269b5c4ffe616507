// The editor with the whole language server, on a dialect's example: a broken line marks the
// editor and fills the `diagnostics` panel, and both clear when it is fixed; hover over a drive
// command or keyword shows its reference text in a tooltip; completion offers the dialect's
// words in a popup; F12 and Ctrl-click go to a name's definition.
import { cursorLine, goToLineEnd, lineOf, wordBox } from "./helpers.mjs";

async function brokenLineIsMarkedAndCleared(page, line, shot) {
  await goToLineEnd(page, line);
  await page.keyboard.type(" )(");
  await page.locator("[data-testid=diagnostics] li").first().waitFor({ timeout: 10000 });
  await page.locator("[data-testid=editor] .cm-lintRange-error").first().waitFor();
  const text = await page.locator("[data-testid=diagnostics] li").first().textContent();
  if (!text.startsWith(`${line}:`)) throw new Error(`the diagnostic is not on ${line}: ${text}`);
  await shot("1_diagnostic");
  // Backspace rather than undo: a slow machine's typing may fall into several undo groups.
  for (let i = 0; i < 3; ++i) await page.keyboard.press("Backspace");
  await page.waitForFunction(() => !document.querySelector("[data-testid=diagnostics] li") &&
    !document.querySelector("[data-testid=editor] .cm-lintRange-error"), null, { timeout: 10000 });
}

async function hoverShowsTheReference(page, { line, word, text }) {
  const at = await wordBox(page, line, word);
  await page.mouse.move(at.x, at.y);
  const tooltip = page.locator(".cm-tooltip-hover");
  await tooltip.waitFor({ timeout: 10000 });
  const shown = await tooltip.textContent();
  if (!text.test(shown)) throw new Error(`hover over ${word}: ${shown}`);
  await page.mouse.move(0, 0);
  await tooltip.waitFor({ state: "detached", timeout: 10000 });
}

// A new last line with `prefix` typed: the popup offers `label`; Escape and the line removed.
async function completionOffers(page, { prefix, labels }) {
  const before = await page.evaluate(() => window.studio.editor.state.doc.toString());
  await page.evaluate(() => {
    const view = window.studio.editor;
    view.dispatch({ selection: { anchor: view.state.doc.length }, scrollIntoView: true });
    view.focus();
  });
  await page.keyboard.press("Enter");
  await page.keyboard.type(prefix);
  const popup = page.locator(".cm-tooltip-autocomplete");
  await popup.waitFor({ timeout: 10000 });
  for (const label of labels) {
    await popup.locator(".cm-completionLabel", { hasText: new RegExp(`^${label}$`) }).first()
      .waitFor({ timeout: 10000 });
  }
  await page.keyboard.press("Escape");
  await popup.waitFor({ state: "detached" });
  for (let i = 0; i <= prefix.length; ++i) await page.keyboard.press("Backspace");
  const after = await page.evaluate(() => window.studio.editor.state.doc.toString());
  if (after !== before) throw new Error("completion: the document did not come back");
}

// From a use of a name, F12 and then a Ctrl-click move the cursor to its declaration's line.
async function definitionMovesTheCursor(page, { use, name, declaredAt }) {
  await goToLineEnd(page, use);
  await page.evaluate(([n, w]) => {
    const view = window.studio.editor;
    const l = view.state.doc.line(n);
    view.dispatch({ selection: { anchor: l.from + l.text.indexOf(w) } });
  }, [use, name]);
  await page.keyboard.press("F12");
  await page.waitForFunction((n) => {
    const view = window.studio.editor;
    return view.state.doc.lineAt(view.state.selection.main.head).number === n;
  }, declaredAt, { timeout: 10000 });
  const at = await wordBox(page, use, name);
  await page.keyboard.down("Control");
  await page.mouse.click(at.x, at.y);
  await page.keyboard.up("Control");
  await page.waitForFunction((n) => {
    const view = window.studio.editor;
    return view.state.doc.lineAt(view.state.selection.main.head).number === n;
  }, declaredAt, { timeout: 10000 });
  if (await cursorLine(page) !== declaredAt) throw new Error(`${name}: not at ${declaredAt}`);
}

// `c.lsp`: { broken: text of a line to break, hover: {text, word, shows}, complete: {prefix,
// labels}, definition: {text, name, declared} } (lines by their text in c.file).
export async function languageServerSteps(page, c, shot) {
  const { lsp } = c;
  await brokenLineIsMarkedAndCleared(page, lineOf(c.file, lsp.broken), shot);
  await hoverShowsTheReference(page, { line: lineOf(c.file, lsp.hover.text), word: lsp.hover.word,
    text: lsp.hover.shows });
  await completionOffers(page, lsp.complete);
  await definitionMovesTheCursor(page, { use: lineOf(c.file, lsp.definition.text),
    name: lsp.definition.name, declaredAt: lineOf(c.file, lsp.definition.declared) });
}
