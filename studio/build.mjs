// Builds the studio's page into a folder (the build's studio/): one bundle of src/main.js with
// its CSS, and static/index.html. Fails when the bundle is 1 MB or more gzipped (issue 46).
// Usage: node build.mjs OUT_DIR
import * as esbuild from "esbuild";
import { copyFileSync, mkdirSync, readFileSync, readdirSync } from "node:fs";
import { join, dirname } from "node:path";
import { fileURLToPath } from "node:url";
import { gzipSync } from "node:zlib";

const here = dirname(fileURLToPath(import.meta.url));
const out = process.argv[2];
if (!out) {
  console.error("usage: node build.mjs OUT_DIR");
  process.exit(2);
}
mkdirSync(out, { recursive: true });
await esbuild.build({
  entryPoints: [join(here, "src/main.js")],
  bundle: true,
  minify: true,
  format: "esm",
  target: "es2020",
  outdir: out,
  logLevel: "warning",
});
for (const name of readdirSync(join(here, "static"))) {
  copyFileSync(join(here, "static", name), join(out, name));
}
const limit = 1024 * 1024;
let total = 0;
for (const name of ["main.js", "main.css", "index.html"]) {
  total += gzipSync(readFileSync(join(out, name))).length;
}
console.log(`studio page: ${out} (${(total / 1024).toFixed(0)} KiB gzipped)`);
if (total >= limit) {
  console.error(`the page is ${total} bytes gzipped, over the 1 MB budget`);
  process.exit(1);
}
