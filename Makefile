# Short commands over CMake, as the course's users typed them: make, make run, make test, make doc.
# Every target first installs missing Debian packages (scripts/setup-debian.sh, a no-op when all
# are there).

BUILD      ?= build
BUILD_ASAN ?= build-asan
BUILD_CLANG ?= build-clang
BUILD_FUZZ ?= build-fuzz
CMAKE_ARGS ?=
OUT        ?= out

.PHONY: all setup build run test test-sanitize test-clang fuzz bench-kernels charts doc format clean \
        lab-check lab-handout

all: build

setup:
	@bash scripts/setup-debian.sh

$(BUILD)/build.ninja: | setup
	cmake -S . -B $(BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Release $(CMAKE_ARGS)

build: setup $(BUILD)/build.ninja
	cmake --build $(BUILD)

# Opens the viewer on the default scene (without a display: `xvfb-run -a make run`, or use
# `facet render`; the viewer says so).
run: build
	$(BUILD)/app/facet-view assets/default.scene

# The viewer's window tests start their own virtual display (xvfb-run -a) and input (xdotool).
# Then the skipped tests and why (scripts/test-summary.sh), keeping ctest's exit status.
test: build
	cd $(BUILD) && ctest --output-on-failure -j 2; s=$$?; bash $(CURDIR)/scripts/test-summary.sh; exit $$s

# The lab kit (docs/lab.md): the course's steps checked in order against facet, with the step
# files the build uses (lab/solution by default; CMAKE_ARGS=-DFACET_LAB_SOLUTION=OFF for the
# stubs); and a student folder with the stubs (DIR=path, COURSE=the course data folder).
lab-check: setup $(BUILD)/build.ninja
	cmake --build $(BUILD) --target lab_check
	$(BUILD)/lab/lab_check

COURSE ?= ../shared/data/course
lab-handout:
	bash scripts/lab-handout.sh "$(DIR)" "$(COURSE)"

# The same tests built with AddressSanitizer and UndefinedBehaviorSanitizer (what CI also runs).
# Built with Clang and warnings as errors, so this one build also proves what `make test-clang`
# does (the engine, the CLI and the tests build warning-free with Clang and pass), and CI runs it
# instead of a second Clang build (10 of CI's 50 minutes). Clang's UBSan checks more than GCC's
# (float-to-integer overflow, the class of the OFF colour finding). -O1 with line tables only, as
# the sanitizers' documentation suggests: reports still name lines, and the build is what took
# the time (17 of the step's 23 minutes at -O2 -g, 8 of them compiling the Highway span variants).
# SANITIZE_SKIP leaves out the tests that only re-run code the other tests already cover on
# larger inputs, for numbers (172 s of test time under ASan, about 85 s of the step at -j2): the view-angle and
# highlight sweeps (their code is covered by the fast-vs-reference cases), the full camera-path
# sweep (the quick sweep_paths tests run the same paths), the bunny's SIMD comparison (every
# target is checked on the course scenes and Spot) and the lab handout's test (a second, plain
# build of facet from the clone: nothing in it is instrumented).
SANITIZE_SKIP ?= ^(ViewAngle\.|Highlights\.|SweepCameraPaths\.FullSweep|Scenes/SimdTargets\..*bunny|LabHandout\.)
test-sanitize: setup
	cmake -S . -B $(BUILD_ASAN) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only" -DCMAKE_CXX_COMPILER=clang++ \
	  -DFACET_WERROR=ON -DFACET_SANITIZE=address,undefined -DFACET_BUILD_VIEWER=OFF $(CMAKE_ARGS)
	cmake --build $(BUILD_ASAN)
	cd $(BUILD_ASAN) && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
	  LSAN_OPTIONS=suppressions=$(CURDIR)/scripts/lsan-suppressions.txt \
	  ctest --output-on-failure -j 2 -E '$(SANITIZE_SKIP)'; s=$$?; \
	  bash $(CURDIR)/scripts/test-summary.sh; exit $$s

# The engine, the CLI and the tests built with Clang in Release, warnings as errors (the viewer
# stays with GCC's build), and run. CI leaves it to test-sanitize, which builds the same with
# Clang and -Werror.
test-clang: setup
	cmake -S . -B $(BUILD_CLANG) -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++ \
	  -DFACET_WERROR=ON -DFACET_BUILD_VIEWER=OFF $(CMAKE_ARGS)
	cmake --build $(BUILD_CLANG)
	cd $(BUILD_CLANG) && ctest --output-on-failure -j 2

# The libFuzzer targets (fuzz/) with AddressSanitizer and UndefinedBehaviorSanitizer, each run for
# FUZZ_SECONDS on its seed corpus; fails on any finding (docs/fuzzing.md). -O1 with line tables
# only, as libFuzzer's documentation suggests: stack traces name lines, and it builds fast.
FUZZ_SECONDS ?= 60
FUZZ_TARGETS ?= scene off obj texture render
fuzz: setup
	cmake -S . -B $(BUILD_FUZZ) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only" \
	  -DCMAKE_CXX_COMPILER=clang++ -DFACET_FUZZ=ON -DFACET_SANITIZE=address,undefined \
	  -DFACET_BUILD_TESTS=OFF -DFACET_BUILD_VIEWER=OFF $(CMAKE_ARGS)
	cmake --build $(BUILD_FUZZ) --target fuzz_targets
	bash scripts/run-fuzz.sh $(BUILD_FUZZ) $(FUZZ_SECONDS) $(FUZZ_TARGETS)

# Kernel micro-benchmarks (tests/engine/kernels_bench.cpp) from the Release build. Each runs 5 times and
# only the aggregates (mean, median, stddev, cv) are shown, since one run on a busy machine can be
# far off; compare medians. BENCH_ARGS overrides, e.g. BENCH_ARGS=--benchmark_filter=shade/.
BENCH_ARGS ?= --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
bench-kernels: setup $(BUILD)/build.ninja
	cmake --build $(BUILD) --target kernels_bench
	$(BUILD)/tests/engine/kernels_bench $(BENCH_ARGS)

# The speed-against-accuracy charts of issue 6, committed under docs/: `facet accuracy` on the
# course scenes and Spot (docs/accuracy/), and every stability sweep (docs/sweeps/); named with
# -o, since by default both write to a new folder. Run it on an idle machine: the charts carry
# the load average and say when it was busy. A few minutes (docs/accuracy.md).
SHARED ?= ../shared/data
charts: build
	$(BUILD)/app/facet accuracy $(SHARED)/course/example0.scene $(SHARED)/course/example1.scene \
	  $(SHARED)/course/example2.scene $(SHARED)/course/example_textured.scene \
	  $(SHARED)/scenes/spot_1280x720.scene --texture $(SHARED)/course/brick.jpg -o docs/accuracy
	$(BUILD)/app/facet sweeps -o docs/sweeps

doc: setup
	@command -v doxygen >/dev/null || bash scripts/setup-debian.sh doxygen
	mkdir -p $(BUILD)/doc
	( cat docs/Doxyfile; echo "OUTPUT_DIRECTORY = $(BUILD)/doc" ) | doxygen -
	@echo "Open $(abspath $(BUILD))/doc/html/index.html"

format:
	clang-format -i $$(git ls-files '*.cpp' '*.hpp' | grep -v '^third_party/')

clean:
	rm -rf $(BUILD) $(BUILD_ASAN) $(BUILD_CLANG) $(BUILD_FUZZ) $(OUT)
