extends GutTest
## The five machines' looks: each has its own art, ring, pins, pockets, cabinet and panel
## colours and name plate; an unknown name falls back to Classic; the art stays loaded.

## The palette fields that must differ between every two machines.
const OWN_FIELDS: Array[String] = [
	"art_path", "ring", "petal", "plate", "backdrop_top", "panel_border", "title", "plate_style"
]


func test_every_machine_has_its_own_look() -> void:
	var palettes: Array[FasciaPalette] = []
	for name in FasciaNames.NAMES:
		var palette := FasciaBook.palette_of(name)
		assert_eq(palette.name, name)
		var art := FasciaBook.art_of(palette)
		assert_not_null(art, "%s has its art (%s)" % [name, palette.art_path])
		if art != null:
			assert_eq(art.get_size(), Vector2(1000, 1000), name + ": the art is 1000 px square")
		palettes.append(palette)
	for field in OWN_FIELDS:
		var seen := {}
		for palette in palettes:
			seen[str(palette.get(field))] = true
		assert_eq(seen.size(), palettes.size(), "every machine has its own " + field)


func test_classic_keeps_the_chapters_machine() -> void:
	var classic := FasciaBook.palette_of(FasciaNames.CLASSIC)
	assert_eq(classic.art_path, "res://assets/pachinko/fascia.svg", "the moon face and dragon")
	assert_eq(classic.ring, Color("5b2a86"), "the purple enamel ring")
	assert_eq(FasciaBook.palette_of("disco"), classic, "an unknown name wears Classic")


func test_the_art_stays_loaded_for_pictures_that_hold_only_its_rid() -> void:
	var palette := FasciaBook.palette_of("garden")
	var first := FasciaBook.art_of(palette)
	var id := first.get_instance_id()
	first = null
	assert_eq(FasciaBook.art_of(palette).get_instance_id(), id, "the same texture, kept")


func test_the_name_plate_fits_over_the_top_of_the_ring() -> void:
	var level := BoardLoader.load_board("res://levels/pachinko/classic.board").level
	var plate := NamePlate.rect_of(level, 60.0)
	var top := level.ring_center.y - level.ring_radius
	assert_between(plate.get_center().y, top - 22.0, top, "centred on the ring band")
	assert_gt(plate.position.y, level.ring_center.y - level.ring_radius * 1.1, "on the plate")
	assert_eq(plate.size.x, NamePlate.MIN_WIDTH, "a short name gets the smallest plate")
	assert_eq(NamePlate.rect_of(level, 900.0).size.x, NamePlate.MAX_WIDTH, "a long one is held")


func test_the_cabinet_is_painted_in_the_machines_colours() -> void:
	var neon := FasciaBook.palette_of("neon")
	var image := CabinetBackdrop.paint(Vector2i(8, 8), neon.backdrop_top, neon.backdrop_bottom)
	assert_almost_eq(image.get_pixel(0, 0).r, neon.backdrop_top.r, 0.05)
	assert_almost_eq(image.get_pixel(7, 7).b, neon.backdrop_bottom.b, 0.05)
