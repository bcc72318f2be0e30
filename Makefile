# camlray: the README's two commands are `make render` and `make test`;
# both install the toolchain first when it is missing (scripts/setup.sh).
SHELL := /bin/bash
CAMLRAY := _build/install/default/bin/camlray
SCENE ?= scenes/default.scn

.PHONY: all setup build render test bench fuzz stress clean mc-convergence conformance \
  conformance-parse messages-coverage gallery radiosity afl

all: build

setup:
	@bash scripts/setup.sh

build: setup
	@dune build @install 2>&1 | head -100; test $${PIPESTATUS[0]} -eq 0

render: build
	@mkdir -p out
	$(CAMLRAY) render $(SCENE) -o out/default.png

test: build
	@bash scripts/run-tests.sh

# Cross-render against POV-Ray (skipped with a message when povray is
# missing): CONFORMANCE_SCENES, size and anti-aliasing can be overridden.
CONFORMANCE_SCENES ?= scenes/whitted-extra
CONFORMANCE_FLAGS ?= -W 320 -H 240 --aa 0.3
conformance: build
	$(CAMLRAY) compare $(CONFORMANCE_SCENES) $(CONFORMANCE_FLAGS) -o out/conformance

bench: build
	dune build bench/whole/whole.exe bench/alloc/alloc.exe
	./_build/default/bench/alloc/alloc.exe scenes/default.scn scenes/seeds/diagrams-snowman.scn
	./_build/default/bench/alloc/alloc.exe --mc 4 scenes/default.scn
	./_build/default/bench/whole/whole.exe
	dune exec --release bench/main.exe

stress: build
	@bash scripts/stress.sh 50

# the long Monte Carlo convergence study (a few minutes on 2 cores)
mc-convergence: build
	dune exec --release test/mc/convergence.exe

# Parser robustness: 10^5 random inputs (FUZZ_N to change), none may raise.
FUZZ_N ?= 100000
fuzz: build
	@dune build test/fuzz/fuzz.exe 2>&1 | grep -v '^Read ' | head -50
	./_build/default/test/fuzz/fuzz.exe $(FUZZ_N)

# AFL++ on an instrumented parser (AFL_SECONDS, default 600)
afl: setup
	@bash scripts/afl.sh

# the seed scenes in both modes -> docs/gallery.png (needs ImageMagick)
gallery: build
	@bash scripts/sheets.sh gallery

# seeds by POV-Ray with radiosity beside camlray's mc mode -> docs/radiosity.png
radiosity: build
	@bash scripts/sheets.sh radiosity

# `camlray check` over POV-Ray's example scenes -> docs/conformance-parse.md
conformance-parse: build
	@bash scripts/conformance-parse.sh

# How many parser error states have a hand-written message (never fails).
messages-coverage:
	@bash scripts/messages-coverage.sh

clean:
	dune clean
