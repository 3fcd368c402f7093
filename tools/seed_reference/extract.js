// Reads the tilt maze tutorial's script.js out of the seed text at run time. The seed
// prints each source line prefixed by its line number, all run together on one text line;
// this splits it back into lines by finding 1, 2, 3, ... in order.
"use strict";
const fs = require("fs");
const path = require("path");

const SEED_DIR = path.resolve(__dirname, "../../../shared/seeds");

/** The seed file that holds the tilt maze tutorial. */
function findSeedFile() {
  for (const name of fs.readdirSync(SEED_DIR).sort()) {
    if (!name.endsWith(".txt")) continue;
    const text = fs.readFileSync(path.join(SEED_DIR, name), "utf8");
    if (text.includes("rollAroundCap") && text.includes("Tilting Maze")) return text;
  }
  throw new Error(`no tilt maze tutorial in ${SEED_DIR}`);
}

/** The tutorial's JavaScript source, one line per original line. */
function extractScript() {
  const line = findSeedFile()
    .split("\n")
    .find((l) => l.includes("const rollAroundCap") && l.includes("function main("));
  if (!line) throw new Error("the tutorial's script.js listing was not found");
  const lines = [];
  let pos = line.indexOf("1");
  let n = 1;
  pos += 1;
  for (;;) {
    const marker = " " + (n + 1);
    let next = line.indexOf(marker, pos);
    // " 12" is not line 12 when it is the start of " 120".
    while (next >= 0 && /\d/.test(line[next + marker.length] || "")) {
      next = line.indexOf(marker, next + 1);
    }
    if (next < 0) {
      lines.push(line.slice(pos));
      break;
    }
    lines.push(line.slice(pos, next));
    pos = next + marker.length;
    n += 1;
  }
  return { source: lines.join("\n"), lineCount: n };
}

module.exports = { extractScript };

if (require.main === module) {
  const { source, lineCount } = extractScript();
  process.stdout.write(source + "\n");
  process.stderr.write(`${lineCount} lines\n`);
}
