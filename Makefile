# stopmo -- one non-recursive GNU Makefile.
#   make            build libcommon.a and every bin/NAME from tools/NAME.c
#   make check      run the TAP tests (tests/t[0-9]*.sh, tests/unit/*.c) with prove
#   make demo       run the example pipelines on data the project generates
#   make bench      benchmarks, printed as ratios against same-run baselines
#   make deps       install missing Debian packages (root) or print the command
#   make install PREFIX=/usr/local
#   make check-sanitize  the whole suite under ASan+UBSan (build-asan/, bin-asan/)
#   make fuzz FUZZ_SECONDS=N  libFuzzer on every reader (tests/fuzz/, clang)
# Extra flags: EXTRA_CFLAGS, EXTRA_CXXFLAGS, EXTRA_LDFLAGS are added to the
# project's own (CFLAGS/CXXFLAGS given on the command line replace only the
# optimisation and debug part: -std=c11, -frounding-math etc. always stay).
# BUILD=dir BINDIR=dir build elsewhere (objects, unit tests; tools).
.SUFFIXES:
.DELETE_ON_ERROR:

PREFIX   ?= /usr/local
CC       ?= cc
CXX      ?= c++
OPT      ?= -O2
CPPFLAGS += -Ilibcommon -I/usr/include/suitesparse -I/usr/include/maxflow-3.0 -I/usr/include/eigen3 \
            -D_POSIX_C_SOURCE=200809L -D_DEFAULT_SOURCE -MMD -MP
CFLAGS   ?= $(OPT) -g
CXXFLAGS ?= $(OPT) -g
BUILD    ?= build
BINDIR   ?= bin
# the project's own flags, kept whatever CFLAGS/CXXFLAGS/LDFLAGS say
STOPMO_CFLAGS   = -std=c11 -Wall -Wextra -pthread
STOPMO_CXXFLAGS = -std=c++17 -Wall -Wextra -Wno-deprecated-copy -pthread -frounding-math \
                  -DCGAL_DISABLE_GMP=0
STOPMO_LDFLAGS  = -pthread -Wl,--as-needed
ALL_CFLAGS   = $(CFLAGS) $(STOPMO_CFLAGS) $(EXTRA_CFLAGS)
ALL_CXXFLAGS = $(CXXFLAGS) $(STOPMO_CXXFLAGS) $(EXTRA_CXXFLAGS)
ALL_LDFLAGS  = $(LDFLAGS) $(STOPMO_LDFLAGS) $(EXTRA_LDFLAGS)
LDLIBS   += -lcholmod -lsuitesparseconfig -lopenblas -llapack -lmaxflow \
            -lOpenMeshCore -lassimp -lpng -lz -lgmp -lmpfr -lfmt -lstdc++ -lm

DEBS = build-essential pkg-config libsuitesparse-dev libopenblas-dev liblapack-dev \
       libcgal-dev libgmp-dev libmpfr-dev libeigen3-dev libopenmesh-dev libassimp-dev \
       libmaxflow-dev libpng-dev zlib1g-dev libfmt-dev xz-utils perl time

LIB_C   := $(wildcard libcommon/*.c)
LIB_CXX := $(wildcard libcommon/*.cpp)
LIB_OBJ := $(LIB_C:%.c=$(BUILD)/%.o) $(LIB_CXX:%.cpp=$(BUILD)/%.o)
TOOLS   := $(patsubst tools/%.c,$(BINDIR)/%,$(wildcard tools/*.c))
UNITS   := $(patsubst tests/unit/%.c,$(BUILD)/tests/%,$(wildcard tests/unit/*.c))
BENCHES := $(patsubst bench/%.c,$(BUILD)/bench/%,$(wildcard bench/*.c))
DEPFILES := $(LIB_OBJ:.o=.d) $(TOOLS:$(BINDIR)/%=$(BUILD)/tools/%.d) $(UNITS:=.d) $(BENCHES:=.d)

all: $(TOOLS) $(UNITS)

# anim-view builds in its page (web/) and three.js (npm 'three' in ./node_modules,
# from make deps), copied to build/web/ whenever its content changes
WEB_ASSETS := web/anim-view.html web/anim-view.js \
              $(addprefix build/web/,three.module.js three.core.js OrbitControls.js three.version)
ifneq ($(MAKECMDGOALS),clean)
$(shell sh web/three-sync.sh build/web)
endif
$(BUILD)/libcommon/web_assets.o: $(WEB_ASSETS)

$(BUILD)/libcommon.a: $(LIB_OBJ)
	@rm -f $@
	$(AR) rcs $@ $^

$(BUILD)/libcommon/%.o: libcommon/%.c
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) $(ALL_CFLAGS) -c -o $@ $<

$(BUILD)/libcommon/%.o: libcommon/%.cpp
	@mkdir -p $(@D)
	$(CXX) $(CPPFLAGS) $(ALL_CXXFLAGS) -c -o $@ $<

$(BUILD)/tools/%.o: tools/%.c
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) $(ALL_CFLAGS) -c -o $@ $<

$(BINDIR)/%: $(BUILD)/tools/%.o $(BUILD)/libcommon.a
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) $(ALL_LDFLAGS) -o $@ $< $(BUILD)/libcommon.a $(LDLIBS)

$(BUILD)/tests/%: tests/unit/%.c tests/unit/tap.h $(BUILD)/libcommon.a
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) -MF $@.d -MT $@ $(ALL_CFLAGS) -Itests/unit $(ALL_LDFLAGS) -o $@ $< $(BUILD)/libcommon.a $(LDLIBS)

$(BUILD)/bench/%: bench/%.c $(BUILD)/libcommon.a
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) -MF $@.d -MT $@ $(ALL_CFLAGS) $(ALL_LDFLAGS) -o $@ $< $(BUILD)/libcommon.a $(LDLIBS)

# deps: install what is missing (Debian); never fails a build that already has it
deps:
	@missing=""; for p in $(DEBS); do \
	  dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q 'ok installed' || missing="$$missing $$p"; \
	done; \
	if [ -z "$$missing" ]; then echo "deps: all Debian packages present"; \
	elif [ "$$(id -u)" = 0 ]; then echo "deps: installing$$missing"; \
	  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $$missing; \
	else echo "deps: missing packages; run:"; echo "  sudo apt-get install$$missing"; exit 1; fi
	@if ! command -v npm >/dev/null; then echo "deps: no npm: anim-view will be built without three.js"; \
	elif npm ls --depth=0 >/dev/null 2>&1; then echo "deps: npm packages present"; \
	else npm install --no-audit --no-fund || echo "deps: npm install failed: anim-view will be built without three.js"; fi

# test-deps: a browser for the anim-view tests (they skip, saying why, without it)
test-deps:
	@if command -v chromium >/dev/null; then :; \
	elif [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null; then echo "test-deps: installing chromium"; \
	  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends chromium >/dev/null 2>&1 || \
	  { apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends chromium; } || \
	  echo "test-deps: chromium could not be installed; the browser tests will be skipped"; \
	else echo "test-deps: no chromium (sudo apt-get install chromium); the browser tests will be skipped"; fi

# bench-deps: the peer of bench/b-dictq.sh, scikit-learn (Debian's, for
# /usr/bin/python3); without it that bench prints why it is skipped
bench-deps:
	@if /usr/bin/python3 -c 'import sklearn' 2>/dev/null; then :; \
	elif [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null; then echo "bench-deps: installing python3-sklearn"; \
	  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends python3-sklearn >/dev/null 2>&1 || \
	  { apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends python3-sklearn; } || \
	  echo "bench-deps: python3-sklearn could not be installed; the scikit-learn comparison will be skipped"; \
	else echo "bench-deps: no scikit-learn (sudo apt-get install python3-sklearn); the scikit-learn comparison will be skipped"; fi

check: deps test-deps
	$(MAKE) all
	prove -j2 --timer tests/t[0-9]*.sh $(UNITS)

demo: deps
	$(MAKE) all
	$(MAKE) -C examples/stopshop demo

bench: deps bench-deps
	$(MAKE) all $(BENCHES)
	sh bench/run.sh

install: all
	install -d $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(PREFIX)/share/man/man1 \
	  $(DESTDIR)$(PREFIX)/share/man/man5 $(DESTDIR)$(PREFIX)/share/man/man7
	install -m 755 $(TOOLS) $(DESTDIR)$(PREFIX)/bin
	install -m 644 $(wildcard man/man1/*.1) $(DESTDIR)$(PREFIX)/share/man/man1
	for s in 5 7; do f=$$(ls man/man$$s/*.$$s 2>/dev/null); \
	  [ -z "$$f" ] || install -m 644 $$f $(DESTDIR)$(PREFIX)/share/man/man$$s; done

# ---- sanitizers: the whole suite under AddressSanitizer + UBSan ----
# A separate build (build-asan/, bin-asan/).  exitcode=86: ASan's default 1
# is the tools' "bad input" code, so test_must_fail would pass on a crash.
# UBSan stops at the first report (halt_on_error) except what
# tests/sanitize/ubsan.supp names.  Leaks are reported (detect_leaks=1);
# tests/sanitize/lsan.supp names only leaks inside OpenMesh and assimp.  STOPMO_SANITIZE=1 tells the tests (ulimit -v
# cannot be combined with ASan's shadow memory).  SANITIZE_TESTS picks a
# subset (default: all).
SAN_FLAGS  = -fsanitize=address,undefined -fno-omit-frame-pointer
# CGAL 5.5.1's Eigen_sparse_matrix copies an uninitialised bool in swap();
# UBSan attributes the load to std::swap<bool> (bits/move.h), which no
# suppression can name without hiding every bool load in std::swap, so the
# one TU that instantiates it (geodesic.cpp, Heat_method_3) is built without
# the bool check in the sanitizer build; every other check stays on there.
SAN_CGAL_FLAGS = -fno-sanitize=bool
$(BUILD)/libcommon/geodesic.o: ALL_CXXFLAGS += $(SAN_CGAL_FLAGS_ON)
SAN_ENV    = ASAN_OPTIONS=exitcode=86:detect_leaks=1:abort_on_error=0:allocator_may_return_null=1 \
             LSAN_OPTIONS=suppressions=$(CURDIR)/tests/sanitize/lsan.supp:print_suppressions=0 \
             UBSAN_OPTIONS=exitcode=86:halt_on_error=1:print_stacktrace=1:suppressions=$(CURDIR)/tests/sanitize/ubsan.supp \
             STOPMO_SANITIZE=1 STOPMO_BIN=$(CURDIR)/bin-asan STOPMO_TRASH=$(CURDIR)/build-asan/trash \
             STOPMO_BUILD=$(CURDIR)/build-asan STOPMO_LINKFLAGS="$(SAN_FLAGS)"
SANITIZE_TESTS ?= tests/t[0-9]*.sh
# the sanitized build is long (CGAL's Booleans under ASan: about 10 min a file
# on a loaded machine), so it runs on every core unless SAN_JOBS says otherwise
SAN_JOBS ?= $(shell nproc 2>/dev/null || echo 2)
check-sanitize: deps
	$(MAKE) -j$(SAN_JOBS) BUILD=build-asan BINDIR=bin-asan OPT=-O1 EXTRA_CFLAGS="$(SAN_FLAGS)" \
	  EXTRA_CXXFLAGS="$(SAN_FLAGS)" EXTRA_LDFLAGS="$(SAN_FLAGS)" \
	  SAN_CGAL_FLAGS_ON="$(SAN_CGAL_FLAGS)" all
	$(SAN_ENV) prove -j2 --timer $(SANITIZE_TESTS) $(patsubst $(BUILD)/%,build-asan/%,$(UNITS))

# ---- fuzzing: libFuzzer harnesses of every reader (tests/fuzz/) ----
FUZZ_SECONDS ?= 60
fuzz-deps:
	@command -v clang >/dev/null || { [ "$$(id -u)" = 0 ] && apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends clang; }
fuzz: deps fuzz-deps
	$(MAKE) -f tests/fuzz/fuzz.mk FUZZ_SECONDS=$(FUZZ_SECONDS)
# the kept fuzz inputs through the sanitized harnesses (a few minutes; CI)
check-fuzz: deps fuzz-deps
	$(MAKE) -f tests/fuzz/fuzz.mk replay

clean:
	rm -rf build bin build-asan bin-asan build-fuzz

.PHONY: all deps test-deps bench-deps check check-sanitize fuzz fuzz-deps check-fuzz demo bench install clean
.PRECIOUS: $(BUILD)/tools/%.o
-include $(DEPFILES)
