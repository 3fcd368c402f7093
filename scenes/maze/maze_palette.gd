class_name MazePalette
extends RefCounted
## The seed's palette (coolors f06449-ede6e3-7d82b8-36382e-613f75), shared by the maze views.

const BACKGROUND := Color("ede6e3")
const WALL := Color("36382e")
const JOYSTICK := Color("210124")
const BALL := Color("f06449")
const GOAL := Color("7d82b8")
const TEXT := Color("210124")
const HOLE := Color("000000")
const HOLE_RIM := Color("5a5a5a")
const HOLE_LOST := Color("e0201a")
const MARK := Color("ffffff")
const HARD := Color("613f75")
