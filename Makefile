# Short commands over CMake, as the course's users typed them: make, make run, make test, make doc.
# Every target first installs missing Debian packages (scripts/setup-debian.sh, a no-op when all
# are there).

BUILD      ?= build
BUILD_ASAN ?= build-asan
CMAKE_ARGS ?=
OUT        ?= out

.PHONY: all setup build run test test-sanitize doc format clean

all: build

setup:
	@bash scripts/setup-debian.sh

$(BUILD)/build.ninja: | setup
	cmake -S . -B $(BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Release $(CMAKE_ARGS)

build: setup $(BUILD)/build.ninja
	cmake --build $(BUILD)

# Until the viewer exists, "run" renders the default scene to a PNG and says where it is.
run: build
	@mkdir -p $(OUT)
	$(BUILD)/app/facet render assets/default.scene -o $(OUT)/default.png --cull --stats
	@echo "Open $(OUT)/default.png to see the default scene."

test: build
	cd $(BUILD) && ctest --output-on-failure -j 2

# The same tests built with AddressSanitizer and UndefinedBehaviorSanitizer (what CI also runs).
test-sanitize: setup
	cmake -S . -B $(BUILD_ASAN) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DFACET_SANITIZE=address,undefined -DFACET_BUILD_VIEWER=OFF $(CMAKE_ARGS)
	cmake --build $(BUILD_ASAN)
	cd $(BUILD_ASAN) && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
	  ctest --output-on-failure -j 2

doc: setup
	@command -v doxygen >/dev/null || bash scripts/setup-debian.sh doxygen
	doxygen docs/Doxyfile
	@echo "Open $(BUILD)/doc/html/index.html"

format:
	clang-format -i $$(git ls-files '*.cpp' '*.hpp' | grep -v '^third_party/')

clean:
	rm -rf $(BUILD) $(BUILD_ASAN) $(OUT)
