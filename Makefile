# stopmo -- one non-recursive GNU Makefile.
#   make            build libcommon.a and every bin/NAME from tools/NAME.c
#   make check      run the TAP tests (tests/t[0-9]*.sh, tests/unit/*.c) with prove
#   make demo       run the example pipelines on data the project generates
#   make bench      benchmarks, printed as ratios against same-run baselines
#   make deps       install missing Debian packages (root) or print the command
#   make install PREFIX=/usr/local
.SUFFIXES:
.DELETE_ON_ERROR:

PREFIX   ?= /usr/local
CC       ?= cc
CXX      ?= c++
OPT      ?= -O2
CPPFLAGS += -Ilibcommon -I/usr/include/suitesparse -I/usr/include/maxflow-3.0 -I/usr/include/eigen3 \
            -D_POSIX_C_SOURCE=200809L -D_DEFAULT_SOURCE -MMD -MP
CFLAGS   ?= $(OPT) -g
CFLAGS   += -std=c11 -Wall -Wextra -pthread
CXXFLAGS ?= $(OPT) -g
CXXFLAGS += -std=c++17 -Wall -Wextra -Wno-deprecated-copy -pthread -frounding-math \
            -DCGAL_DISABLE_GMP=0
LDFLAGS  += -pthread -Wl,--as-needed
LDLIBS   += -lcholmod -lsuitesparseconfig -lopenblas -llapack -lmaxflow \
            -lOpenMeshCore -lassimp -lpng -lz -lgmp -lmpfr -lstdc++ -lm

DEBS = build-essential pkg-config libsuitesparse-dev libopenblas-dev liblapack-dev \
       libcgal-dev libgmp-dev libmpfr-dev libeigen3-dev libopenmesh-dev libassimp-dev \
       libmaxflow-dev libpng-dev zlib1g-dev xz-utils perl

LIB_C   := $(wildcard libcommon/*.c)
LIB_CXX := $(wildcard libcommon/*.cpp)
LIB_OBJ := $(LIB_C:%.c=build/%.o) $(LIB_CXX:%.cpp=build/%.o)
TOOLS   := $(patsubst tools/%.c,bin/%,$(wildcard tools/*.c))
UNITS   := $(patsubst tests/unit/%.c,build/tests/%,$(wildcard tests/unit/*.c))
BENCHES := $(patsubst bench/%.c,build/bench/%,$(wildcard bench/*.c))
DEPFILES := $(LIB_OBJ:.o=.d) $(TOOLS:bin/%=build/tools/%.d) $(UNITS:=.d) $(BENCHES:=.d)

all: $(TOOLS) $(UNITS)

# anim-view builds in its page (web/) and three.js (npm 'three' in ./node_modules,
# from make deps), copied to build/web/ whenever its content changes
WEB_ASSETS := web/anim-view.html web/anim-view.js \
              $(addprefix build/web/,three.module.js three.core.js OrbitControls.js three.version)
ifneq ($(MAKECMDGOALS),clean)
$(shell sh web/three-sync.sh build/web)
endif
build/libcommon/web_assets.o: $(WEB_ASSETS)

build/libcommon.a: $(LIB_OBJ)
	@rm -f $@
	$(AR) rcs $@ $^

build/libcommon/%.o: libcommon/%.c
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) $(CFLAGS) -c -o $@ $<

build/libcommon/%.o: libcommon/%.cpp
	@mkdir -p $(@D)
	$(CXX) $(CPPFLAGS) $(CXXFLAGS) -c -o $@ $<

build/tools/%.o: tools/%.c
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) $(CFLAGS) -c -o $@ $<

bin/%: build/tools/%.o build/libcommon.a
	@mkdir -p $(@D)
	$(CC) $(LDFLAGS) -o $@ $< build/libcommon.a $(LDLIBS)

build/tests/%: tests/unit/%.c tests/unit/tap.h build/libcommon.a
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) -MF $@.d -MT $@ $(CFLAGS) -Itests/unit $(LDFLAGS) -o $@ $< build/libcommon.a $(LDLIBS)

build/bench/%: bench/%.c build/libcommon.a
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) -MF $@.d -MT $@ $(CFLAGS) $(LDFLAGS) -o $@ $< build/libcommon.a $(LDLIBS)

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

check: deps test-deps
	$(MAKE) all
	prove -j2 --timer tests/t[0-9]*.sh $(UNITS)

demo: deps
	$(MAKE) all
	$(MAKE) -C examples/stopshop demo

bench: deps
	$(MAKE) all $(BENCHES)
	sh bench/run.sh

install: all
	install -d $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(PREFIX)/share/man/man1 \
	  $(DESTDIR)$(PREFIX)/share/man/man5 $(DESTDIR)$(PREFIX)/share/man/man7
	install -m 755 $(TOOLS) $(DESTDIR)$(PREFIX)/bin
	install -m 644 $(wildcard man/man1/*.1) $(DESTDIR)$(PREFIX)/share/man/man1
	for s in 5 7; do f=$$(ls man/man$$s/*.$$s 2>/dev/null); \
	  [ -z "$$f" ] || install -m 644 $$f $(DESTDIR)$(PREFIX)/share/man/man$$s; done

clean:
	rm -rf build bin

.PHONY: all deps test-deps check demo bench install clean
.PRECIOUS: build/tools/%.o
-include $(DEPFILES)
