# The two commands of the contract (`make run`, `make test`) and a few helpers.
# CMake does the real work; this file only sequences it. The build directory is
# configured once; later runs let CMake's own dependency tracking decide what to redo.

BUILD_DIR ?= build
BUILD_TYPE ?= Release
JOBS ?= 2
CMAKE ?= cmake
CTEST ?= ctest
CLANG_FORMAT ?= clang-format

.PHONY: all deps configure build test fuzz run bench load clean format

all: build

deps:
	./scripts/install-deps.sh

# Configure only when the tree has no generated build system yet (first build, or a
# configure that failed half-way) or was configured without tests; an existing tree reconfigures itself when a
# CMakeLists.txt changes, so re-running cmake here would only cost time.
# BUILD_TESTING is explicit because CGAL's CMake config declares it OFF when
# find_package(CGAL) runs before include(CTest), which would silently drop every test.
CMAKE_FLAGS := -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) -DIMPLICITIZER_WERROR=ON -DBUILD_TESTING=ON
configure:
	@if [ ! -f $(BUILD_DIR)/CMakeCache.txt ] || { [ ! -f $(BUILD_DIR)/Makefile ] && [ ! -f $(BUILD_DIR)/build.ninja ]; } \
	    || grep -q '^BUILD_TESTING:BOOL=OFF' $(BUILD_DIR)/CMakeCache.txt; then \
	  echo "$(CMAKE) -S . -B $(BUILD_DIR) $(CMAKE_FLAGS)"; \
	  $(CMAKE) -S . -B $(BUILD_DIR) $(CMAKE_FLAGS); \
	fi

build: configure
	$(CMAKE) --build $(BUILD_DIR) -j$(JOBS)

# `test` and `run` install what is missing first; `build` alone does not, so that it
# works without root on a machine that already has everything.
# After ctest, a bounded libFuzzer run (FUZZ_SECONDS per target, in build-fuzz/ with
# clang; skipped with a message when clang cannot link libFuzzer). `make fuzz` is the
# longer run of docs/fuzzing.md.
FUZZ_SECONDS ?= 20
test: deps
	$(MAKE) build
	$(CTEST) --test-dir $(BUILD_DIR) --output-on-failure --no-tests=error -j$(JOBS)
	FUZZ_SEED=1 ./scripts/fuzz.sh --seconds $(FUZZ_SECONDS) --jobs $(JOBS)

fuzz: deps
	./scripts/fuzz.sh --seconds 300 --jobs $(JOBS)

# Ctrl-C stops the server gracefully (SIGINT: in-flight work finishes or is cancelled).
run: deps
	$(MAKE) build
	$(BUILD_DIR)/bin/implicitizer-server --host 127.0.0.1 --port 8080 --static clients/web

bench:
	$(MAKE) build
	$(BUILD_DIR)/bin/implicitizer-bench

# Load benchmark with wrk (docs/benchmarks.md, "Load"); about 70 s with the defaults.
# Not a test: it prints throughput and latency, and fails only on wrong behaviour
# under overload (see bench/load/run_load.sh).
load: deps
	$(MAKE) build
	SERVER=$(BUILD_DIR)/bin/implicitizer-server bench/load/run_load.sh

clean:
	rm -rf $(BUILD_DIR)

FORMAT_DIRS := lib server clients tests bench
format:
	find $(FORMAT_DIRS) -type f \( -name '*.cpp' -o -name '*.hpp' -o -name '*.cc' -o -name '*.h' \) \
	  -not -path '*/node_modules/*' -print0 | xargs -0 -r $(CLANG_FORMAT) -i
