# The README's commands. Each installs what is missing first (scripts/install-deps.sh is idempotent).
BUILD_DIR ?= build
BUILD_TYPE ?= Release
JOBS ?= $(shell nproc)
VILLA := $(BUILD_DIR)/cli/villa

.PHONY: all deps configure build run test bench dataset clean

all: build

deps:
	@bash scripts/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD_DIR) -G Ninja -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) > /dev/null

build: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS)

# The main job on built-in defaults; prints where its outputs are.
run: build
	@bash scripts/main-job.sh $(VILLA) out

test: build
	@cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

bench: build
	@bash scripts/bench.sh $(BUILD_DIR)

# The reference dataset in datasets/, regenerated end to end (byte-identical to the committed one).
dataset: build
	@bash scripts/make-dataset.sh $(VILLA)

clean:
	rm -rf $(BUILD_DIR)
