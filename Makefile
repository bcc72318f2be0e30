# camlray: the README's two commands are `make render` and `make test`;
# both install the toolchain first when it is missing (scripts/setup.sh).
SHELL := /bin/bash
CAMLRAY := _build/install/default/bin/camlray
SCENE ?= scenes/default.scn

.PHONY: all setup build render test bench fuzz clean conformance

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
	dune exec --release bench/main.exe

clean:
	dune clean
