// Records reference trajectories from the tilt maze tutorial's own JavaScript.
//
// Reads the tutorial's script out of ../shared/seeds at run time (extract.js), runs it
// under Node's vm with a stub DOM (elements that accept styles and children, no drawing),
// then drives scripted tilts through its own mousedown/mousemove handlers and calls its
// main() once per 16 ms frame. Each scenario puts one ball somewhere on the classic maze
// and writes the ball's position and velocity after every frame (px and px/frame) to
// tests/fixtures/seed_reference/<name>.json. No tutorial code is stored: only numbers.
//
// Run: node tools/seed_reference/record.js   (or: make seed-reference)
"use strict";
const fs = require("fs");
const path = require("path");
const vm = require("vm");
const { extractScript } = require("./extract.js");
const SCENARIOS = require("./scenarios.js");

const OUT_DIR = path.resolve(__dirname, "../../tests/fixtures/seed_reference");
/** The tutorial's frame: its main() divides elapsed ms by 16. */
const FRAME_MS = 16;
/** The tutorial turns 1 px of joystick travel into 0.8° of tilt. */
const DEG_PER_PX = 0.8;

function stubElement() {
  const el = {
    style: { cssText: "" },
    innerHTML: "",
    children: [],
    listeners: {},
    setAttribute() {},
    appendChild(child) { el.children.push(child); },
    removeChild(child) { el.children = el.children.filter((c) => c !== child); },
    addEventListener(type, fn) { el.listeners[type] = fn; },
  };
  return el;
}

/** A fresh tutorial in its own vm context, with the handles the scenarios need. */
function loadTutorial(source) {
  const elements = {};
  const windowListeners = {};
  const context = {
    console,
    Math,
    Error,
    document: {
      getElementById: (id) => (elements[id] = elements[id] || stubElement()),
      createElement: () => stubElement(),
    },
    window: {
      addEventListener: (type, fn) => { windowListeners[type] = fn; },
      requestAnimationFrame: () => 0,  // frames are driven by hand below
    },
  };
  vm.createContext(context);
  vm.runInContext(source, context, { filename: "seed-script.js" });
  // Reads and writes the tutorial's script-level `let` bindings, which only code running
  // in the same context can see.
  vm.runInContext(
    `function __place(x, y) {
       balls = [{ x: x, y: y, velocityX: 0, velocityY: 0 }];
     }
     function __frame(t) {
       gameInProgress = true;        // a ball in the goal would end the run
       previousTimestamp = t - ${FRAME_MS};
       main(t);
       const b = balls[0];
       return [b.x, b.y, b.velocityX, b.velocityY];
     }`,
    context
  );
  return { context, elements, windowListeners };
}

function tiltTo(tutorial, tiltDeg) {
  const dx = Math.round(tiltDeg[0] / DEG_PER_PX);
  const dy = Math.round(tiltDeg[1] / DEG_PER_PX);
  tutorial.windowListeners.mousemove({ clientX: dx, clientY: dy });
}

function record(source, scenario) {
  const tutorial = loadTutorial(source);
  tutorial.context.__place(scenario.start[0], scenario.start[1]);
  // Grab the joystick at (0, 0): later mouse positions are joystick offsets.
  tutorial.elements["joystick-head"].listeners.mousedown({ clientX: 0, clientY: 0 });
  const frames = [];
  let t = 1000;
  for (let frame = 0; frame < scenario.frames; frame++) {
    const change = scenario.tilts.find((c) => c.frame === frame);
    if (change) tiltTo(tutorial, change.deg);
    t += FRAME_MS;
    frames.push(tutorial.context.__frame(t).map((v) => Math.round(v * 1e6) / 1e6));
  }
  return {
    scenario: scenario.name,
    about: scenario.about,
    units: "px and px per 16 ms frame, y down; each frame is the state after it",
    frame_seconds: FRAME_MS / 1000,
    start: scenario.start,
    tilts: scenario.tilts,
    frames,
  };
}

function main() {
  const { source, lineCount } = extractScript();
  fs.mkdirSync(OUT_DIR, { recursive: true });
  for (const scenario of SCENARIOS) {
    const data = record(source, scenario);
    const file = path.join(OUT_DIR, `${scenario.name}.json`);
    fs.writeFileSync(file, JSON.stringify(data, null, 0).replace(/\],\[/g, "],\n[") + "\n");
    const last = data.frames[data.frames.length - 1];
    console.log(`${scenario.name}: ${data.frames.length} frames, ends at (${last[0]}, ${last[1]})`);
  }
  console.log(`from the tutorial's ${lineCount}-line script; fixtures in ${OUT_DIR}`);
}

main();
