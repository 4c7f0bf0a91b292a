# roofsweep — the two commands a new user needs are `make demo` and `make test`.
# Both install what is missing (Debian packages, needs root), build, and run.

BUILD      ?= build
BUILD_SAN  ?= build-sanitize
JOBS       ?= $(shell nproc)
CMAKE_ARGS ?=
DEPS_FLAGS ?=

.PHONY: all deps build test test-sanitize demo bench format clean qgis-plugin

all: build

deps:
	@scripts/install-deps.sh $(DEPS_FLAGS)

$(BUILD)/build.ninja:
	cmake -S . -B $(BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Release $(CMAKE_ARGS)

build: deps $(BUILD)/build.ninja
	cmake --build $(BUILD) -j $(JOBS)

test: build
	@scripts/install-deps.sh --qgis
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS) --timeout 900

$(BUILD_SAN)/build.ninja:
	cmake -S . -B $(BUILD_SAN) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
	  -DROOFSWEEP_SANITIZE=ON -DROOFSWEEP_BENCHMARKS=OFF $(CMAKE_ARGS)

# Unit tests under AddressSanitizer + UndefinedBehaviorSanitizer.
test-sanitize: deps $(BUILD_SAN)/build.ninja
	cmake --build $(BUILD_SAN) -j $(JOBS)
	cd $(BUILD_SAN) && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
	  LSAN_OPTIONS=suppressions=$(CURDIR)/tests/sanitizer/lsan.supp \
	  ctest --output-on-failure -j $(JOBS) --timeout 1800 -LE slow

demo: build
	scripts/demo.sh $(BUILD)

bench: build
	scripts/bench.sh $(BUILD)

format:
	find algorithms io plugin tests examples -name '*.cc' -o -name '*.h' | xargs clang-format -i

clean:
	rm -rf $(BUILD) $(BUILD_SAN) out

# The QGIS plugin as a zip for Plugins > Install from ZIP.
qgis-plugin:
	@mkdir -p dist
	python3 plugin/qgis/make_zip.py dist/roofsweep_qgis.zip
	@echo "Wrote dist/roofsweep_qgis.zip"
