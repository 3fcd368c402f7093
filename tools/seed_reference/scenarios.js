// The scripted tilts record.js plays on the classic maze (tutorial coordinates, px).
// A cell's centre is (35·column + 17.5, 35·row + 17.5). Tilts are in degrees, x then y,
// whole joystick pixels (0.8° each), at most 12° per axis as the tutorial allows.
"use strict";
module.exports = [
  {
    name: "straight_x",
    about: "rolls right along the top row and bounces off the side of the wall at x = 105",
    start: [17.5, 17.5],
    frames: 120,
    tilts: [{ frame: 0, deg: [12, 0] }],
  },
  {
    name: "straight_y",
    about: "rolls down the first column onto the wall at y = 210",
    start: [17.5, 17.5],
    frames: 150,
    tilts: [{ frame: 0, deg: [0, 12] }],
  },
  {
    name: "diagonal_12_4",
    about: "a (12°, 4°) tilt across the open middle: the per-axis cap rolls it at about 45°",
    start: [122.5, 122.5],
    frames: 90,
    tilts: [{ frame: 0, deg: [12, 4] }],
  },
  {
    name: "diagonal_45",
    about: "a (12°, 12°) tilt from the middle onto the cap at (210, 210), 7 px off its centre",
    start: [122.5, 132.5],
    frames: 90,
    tilts: [{ frame: 0, deg: [12, 12] }],
  },
  {
    name: "round_cap",
    about: "rolls right into the top cap of the wall at x = 210 off-centre and round it",
    start: [157.5, 133.0],
    frames: 70,
    tilts: [{ frame: 0, deg: [12, 0] }],
  },
  {
    name: "head_on_cap",
    about: "rolls straight down into the top cap of the wall at x = 210: it stops dead there",
    start: [210.0, 110.0],
    frames: 40,
    tilts: [{ frame: 0, deg: [0, 12] }],
  },
  {
    name: "off_wall",
    about: "rolls down onto the wall at y = 210, then the tilt turns and it rolls off along it",
    start: [17.5, 157.5],
    frames: 120,
    tilts: [
      { frame: 0, deg: [0, 12] },
      { frame: 40, deg: [8, -4] },
      { frame: 80, deg: [-12, 8] },
    ],
  },
  {
    name: "corner_12_12",
    about: "the joystick at its corner (12°, 12°): the top-left ball rolls straight at the cap at (35, 35) and slides off it",
    start: [17.5, 17.5],
    frames: 600,
    tilts: [{ frame: 0, deg: [12, 12] }],
  },
];
