# Board Studio: every target sets itself up first (tools/setup.sh is idempotent and fast
# when warm). See README.md.
SHELL := /bin/bash
GODOT := tools/godot.sh

.PHONY: play test setup lint format editor shots bench export export-check release release-check check-boards analyze clean seed-reference mutate golden

## make play: the game window with a display, the headless autoplay demo without one
play: setup
	@if [ -n "$$DISPLAY$$WAYLAND_DISPLAY" ]; then \
		$(GODOT) --path . ; \
	else \
		echo "No display: running the headless autoplay demo (see README for the window)."; \
		$(GODOT) --headless --path . -- --autoplay=pachinko --board=classic --seconds=60 --seed=1 && \
		$(GODOT) --headless --path . -- --autoplay=maze --board=classic --seconds=120 --seed=1; \
	fi

## make test: lint, every GUT test headless, the editor smoke check, the game under Xvfb;
## ends "N passed, N failed"
test:
	@tools/setup.sh test
	@tools/run_tests.sh

setup:
	@tools/setup.sh

lint: setup
	@tools/lint.sh

format: setup
	@tools/lint.sh --fix

editor: setup
	$(GODOT) --path . --editor

shots:
	@tools/setup.sh pictures
	@tools/shots.sh

## make check-boards: every board file in levels/ and user://boards/, one JSON line each
check-boards: setup
	@$(GODOT) --headless --path . -- --check-boards

## make analyze: the play analysis of every board, one JSON line each; reports and heat
## maps in build/analysis/ (pachinko: 10000 shots; maze: 20 pilot games in each mode)
analyze: setup
	@for f in levels/pachinko/*.board; do \
		$(GODOT) --headless --path . -- --analyze=pachinko --board=$$(basename $$f .board) || exit 1; \
	done
	@for f in levels/maze/*.board; do \
		$(GODOT) --headless --path . -- --analyze=maze --board=$$(basename $$f .board) || exit 1; \
	done

## make golden: records the golden state hashes again (tests/golden/golden_hashes.json: the
## bench scenes, every board's autoplay, a replay of each game); after a meant physics or
## rules change, with its version bumped. test_golden_hashes.gd checks them in make test.
golden: setup
	@$(GODOT) --headless --path . -s res://tests/golden/record_golden.gd

bench: setup
	@tools/bench.sh

## make mutate [FILE=scripts/app/medals.gd]: mutation testing of the rule files listed in
## tools/mutate/targets.txt (or of FILE), each against its own tests; slow, not in make test.
## The table (file, mutants, killed, score, survivors) goes to build/mutate/table.md.
mutate: setup
	@tools/mutate.sh $(FILE)

export:
	@tools/setup.sh export
	@tools/export.sh

export-check: export
	@tools/export_check.sh

## make release: build/release/board-studio-<version>-linux-x86_64.tar.gz, the game as players
## get it (one folder, its own libraries; see tools/release/build.sh)
release:
	@tools/setup.sh export
	@tools/release/build.sh

## make release-check: the last make release's archive (built first when there is none) in a
## clean Debian 12 root: both autoplays, the window, no build paths (tools/release/check.sh)
release-check:
	@ls build/release/board-studio-*-linux-x86_64.tar.gz >/dev/null 2>&1 || $(MAKE) --no-print-directory release
	@tools/release/launcher_test.sh
	@tools/release/elf_paths_test.sh
	@tools/release/check.sh

clean:
	rm -rf build .godot

## make seed-reference: re-record the tilt maze tutorial's reference runs (needs node)
seed-reference:
	node tools/seed_reference/record.js
