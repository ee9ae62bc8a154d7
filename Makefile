# The two commands of the quick start. Both install what they need first.
#   make demo   build in release, run the main job on a bundled example
#   make test   build in release, run the whole suite through ctest, then CI's second half
#               (scripts/ci-extra.sh: the unit, bad-input and fuzz-replay tests under clang with
#               ASan+UBSan, and GCC's outputs against clang's byte for byte); RAMUS_CI_EXTRA=0
#               skips the second half
MAKEFLAGS += --no-print-directory
BUILD_DIR ?= build/release
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
DEMO ?= examples/trees/broadleaf.ramus

.PHONY: demo test deps configure build clean

deps:
	@bash scripts/install-deps.sh

configure: deps
	@cmake --preset release -S . -B $(BUILD_DIR) >/dev/null

# Everything: the libraries, the ramus executable, the tests and the benchmarks.
build: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS)

# The demo needs only the ramus executable and the stage libraries it links.
demo: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS) --target ramus
	@bash scripts/demo.sh $(BUILD_DIR)/ramus $(DEMO)

# On: CI runs `make test` (.ci/run). Its time on a 2-core machine is in docs/robustness.md.
RAMUS_CI_EXTRA ?= 1

test: build
	@cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)
	@if [ "$(RAMUS_CI_EXTRA)" = 1 ]; then JOBS=$(JOBS) bash scripts/ci-extra.sh; fi

clean:
	rm -rf build out
