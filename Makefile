# Thin layer over scripts/ and CMakePresets.json. The README's two commands:
#   ./scripts/install-deps && make demo     build, then run the main job on the bundled samples -> out/
#   ./scripts/install-deps && make test     build, fetch the real samples, run the whole test suite
PRESET ?= default

.PHONY: all deps configure build samples demo test docs package clean

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

# Rendering and GUI tests need an X server: scripts/run-tests gives them a private one (xvfb-run).
test: build samples
	./scripts/run-tests $(PRESET)

# The C++ API reference: build/docs/api/html/index.html (Doxygen; fails on any warning).
docs:
	./scripts/api-docs build/docs/api

# The Debian package: build/medial_<version>_amd64.deb (CPack).
package: build
	cd build && cpack --config CPackConfig.cmake

clean:
	rm -rf build build-debug out
