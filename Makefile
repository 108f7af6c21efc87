# Set-up commands for a fresh Debian 12 machine (see README.md).
#   make run    install packages, build (Release, build/), run inputs/mpm/disks.ups
#   make test   install packages, build, run the whole test suite (ctest)
#   make build  build only; the executable is build/bin/tephra
BUILD ?= build
JOBS  ?= $(shell nproc)
MAKEFLAGS += --no-print-directory
DECK  ?= inputs/mpm/disks.ups

.PHONY: deps configure build run test clean

deps:
	@bash .ci/install-deps.sh

configure:
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release > /dev/null

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

run: deps build
	@$(BUILD)/bin/tephra $(DECK) --output $(BUILD)/run/disks.uda
	@echo "output written to $(BUILD)/run/disks.uda"

test: deps build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

clean:
	rm -rf $(BUILD)
