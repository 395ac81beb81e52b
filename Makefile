# Thin layer over scripts/ and CMakePresets.json. The README's two commands:
#   ./scripts/install-deps && make demo     build, then run the main job on the bundled samples -> out/
#   ./scripts/install-deps && make test     build, fetch the real samples, run the whole test suite
PRESET ?= default

.PHONY: all deps configure build samples demo test clean

all: build

deps:
	./scripts/install-deps

configure:
	cmake --preset $(PRESET)

build: configure
	cmake --build --preset $(PRESET)

samples:
	./scripts/fetch-samples

demo: build
	./scripts/demo

# Rendering and GUI tests need an X server: xvfb-run gives them a private one.
test: build samples
	xvfb-run -a -s "-screen 0 1920x1200x24" ctest --preset $(PRESET) -j2

clean:
	rm -rf build build-debug out
