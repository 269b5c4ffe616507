// `uprog studio`'s command line (issue 46): loopback by default and quiet; another address
// prints the warning that anyone who reaches it can drive the simulated axis; the page is served;
// a missing page or an unknown dialect is refused with its exit code; SIGTERM stops it cleanly.
// Environment: UPROG (the binary).
import { spawn, spawnSync } from "node:child_process";
import { join, dirname } from "node:path";
import { fileURLToPath } from "node:url";
import assert from "node:assert/strict";
import { test } from "node:test";

const root = join(dirname(fileURLToPath(import.meta.url)), "../..");
const uprog = process.env.UPROG ?? join(root, "build/bin/uprog");
const example = join(root, "examples/gold/first_move.ehl");

// Starts the studio; resolves with its URL and what it printed on stderr so far.
function studio(args) {
  const child = spawn(uprog, ["studio", example, ...args], { stdio: ["ignore", "pipe", "pipe"] });
  let err = "";
  child.stderr.on("data", (d) => { err += d; });
  return new Promise((resolve, reject) => {
    let out = "";
    child.stdout.on("data", (d) => {
      out += d;
      const m = /studio on (http:\/\/\S+)/.exec(out);
      if (m) resolve({ child, url: m[1], stderr: () => err });
    });
    child.on("exit", (code) => reject(new Error(`exited ${code}: ${err}`)));
  });
}

function stopped(child) {
  return new Promise((resolve) => child.on("exit", (code, signal) => resolve({ code, signal })));
}

test("loopback by default: no warning, the page served, SIGTERM ends it with 0", async () => {
  const { child, url, stderr } = await studio(["--listen", "127.0.0.1:0"]);
  assert.match(url, /^http:\/\/127\.0\.0\.1:\d+\/$/);
  const page = await fetch(url);
  assert.equal(page.status, 200);
  assert.match(await page.text(), /data-testid="editor"/);
  assert.equal(stderr(), "");
  const end = stopped(child);
  child.kill("SIGTERM");
  assert.deepEqual(await end, { code: 0, signal: null });
});

// What a child printed on stderr, once it holds `pattern` (stdout and stderr are two pipes: the
// warning may come after the URL), or all of it after two seconds.
async function stderrHolding(stderr, pattern) {
  for (let waited = 0; waited < 2000 && !pattern.test(stderr()); waited += 20)
    await new Promise((resolve) => setTimeout(resolve, 20));
  return stderr();
}

test("another address prints the warning", async () => {
  const { child, url, stderr } = await studio(["--listen", "0.0.0.0:0"]);
  const end = stopped(child);
  try {
    const warning = /anyone who reaches it can drive the simulated axis/;
    assert.match(await stderrHolding(stderr, warning), warning);
    const port = new URL(url).port;
    assert.equal((await fetch(`http://127.0.0.1:${port}/`)).status, 200);
  } finally {
    child.kill("SIGTERM");
    await end;
  }
});

test("no page, a bad address, an unknown dialect: refused", () => {
  const noPage = spawnSync(uprog, ["studio", example, "--page", "/nonexistent", "--listen", "127.0.0.1:0"]);
  assert.equal(noPage.status, 1);
  assert.match(String(noPage.stderr), /no page in \/nonexistent/);
  const badAddress = spawnSync(uprog, ["studio", example, "--listen", "nowhere"]);
  assert.equal(badAddress.status, 2);
  const badDialect = spawnSync(uprog, ["studio", "--dialect", "cobol", "--listen", "127.0.0.1:0"]);
  assert.equal(badDialect.status, 2);
});
