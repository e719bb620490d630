# catena - top-level driver around CMake.
#   make        build build/catena and libcatena
#   make run    install missing packages, build, run the paper's study and the modal study
#   make test   install missing packages, build and run every test (plain and ASan+UBSan)
#               and a 30 s smoke of the libFuzzer harness
#   make install PREFIX=/usr/local   build, then install headers, libcatena.a, libcatena.so,
#               the catena command and lib/pkgconfig/catena.pc (DESTDIR=... stages them)
BUILD ?= build
ASAN_BUILD ?= build-asan
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
PREFIX ?= /usr/local

.PHONY: all deps run install test test-plain test-asan test-fuzz fuzz valgrind bench clean

all: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release >/dev/null
	@cmake --build $(BUILD) -j $(JOBS) -- -s --no-print-directory >/dev/null

deps:
	@bash scripts/deps.sh

run: all
	@bash scripts/paper.sh $(BUILD)/catena
	@bash scripts/modal.sh $(BUILD)

install: all
	DESTDIR="$(DESTDIR)" cmake --install $(BUILD) --prefix "$(PREFIX)"

test: test-plain test-asan test-fuzz

test-plain: all
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

test-asan: deps
	@cmake -S . -B $(ASAN_BUILD) -DCMAKE_BUILD_TYPE=Debug -DCTN_SANITIZE=ON >/dev/null
	@cmake --build $(ASAN_BUILD) -j $(JOBS) -- -s --no-print-directory
	@cd $(ASAN_BUILD) && ASAN_OPTIONS=detect_leaks=1 ctest --output-on-failure -j $(JOBS)

# A short smoke of the libFuzzer harness (the full run: make fuzz FUZZ_SECONDS=1800).
FUZZ_SECONDS ?= 60
test-fuzz: deps
	@bash scripts/fuzz.sh 30 build-fuzz

fuzz: deps
	@bash scripts/fuzz.sh $(FUZZ_SECONDS) build-fuzz

valgrind: all
	@cd $(BUILD) && ctest -T memcheck -E cli_ --output-on-failure

bench: all
	@bash bench/run.sh $(BUILD)

clean:
	rm -rf $(BUILD) $(ASAN_BUILD) build-fuzz
