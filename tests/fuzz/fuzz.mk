# fuzz.mk -- libFuzzer harnesses of every reader (make fuzz FUZZ_SECONDS=N).
# Built with clang (Debian's; `make fuzz` installs it when missing) into
# build-fuzz/: the readers' sources with ASan + UBSan and coverage, each
# harness linked with -fsanitize=fuzzer.  Each target runs FUZZ_SECONDS on
# one process (no -jobs: the machine is shared), its corpus in build-fuzz/corpus/
# NAME seeded from tests/fuzz/corpus/NAME and tests/fuzz/regress/NAME.
# New inputs worth keeping: copy them into tests/fuzz/corpus/NAME (a crash
# input, once fixed, into tests/fuzz/regress/NAME): make check replays both
# through the normal build (tests/unit/fuzz_replay.c).
FUZZ_SECONDS ?= 60
FUZZ_TARGETS ?= mesh meshio gltf columns rings compat holes
FUZZ_CC  ?= clang
FUZZ_CXX ?= clang++
FB := build-fuzz
SAN := -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer
CPPFLAGS := -Ilibcommon -I/usr/include/eigen3 -D_POSIX_C_SOURCE=200809L -D_DEFAULT_SOURCE -D_GNU_SOURCE
CFLAGS   := -O1 -g -std=c11 -pthread $(SAN) -fsanitize=fuzzer-no-link
CXXFLAGS := -O1 -g -std=c++17 -pthread -frounding-math $(SAN) -fsanitize=fuzzer-no-link
LDLIBS   := -lOpenMeshCore -lassimp -lz -lgmp -lmpfr -lfmt -lstdc++ -lm
# the readers and what they call (the closure over their #includes)
SRC := $(shell sh tests/fuzz/deps.sh mesh columns landmarks rings compat_tri compat_holes meshio anim_import)
OBJ := $(SRC:%=$(FB)/%.o)
BIN := $(FUZZ_TARGETS:%=$(FB)/fuzz_%)

run: $(BIN)
	@set -e; for t in $(FUZZ_TARGETS); do \
	  mkdir -p $(FB)/corpus/$$t $(FB)/crash/$$t; \
	  echo "fuzz_$$t: $(FUZZ_SECONDS) s"; \
	  ASAN_OPTIONS=allocator_may_return_null=1 LSAN_OPTIONS=suppressions=$(CURDIR)/tests/sanitize/lsan.supp:print_suppressions=0 \
	  $(FB)/fuzz_$$t -max_total_time=$(FUZZ_SECONDS) -timeout=10 -rss_limit_mb=2048 \
	    -max_len=65536 -print_final_stats=1 -artifact_prefix=$(FB)/crash/$$t/ \
	    $(FB)/corpus/$$t tests/fuzz/corpus/$$t $$(test -d tests/fuzz/regress/$$t && echo tests/fuzz/regress/$$t) \
	    2>$(FB)/fuzz_$$t.log || { tail -40 $(FB)/fuzz_$$t.log; exit 1; }; \
	  grep -E "^stat::number_of_executed_units|^stat::peak_rss_mb" $(FB)/fuzz_$$t.log || true; \
	  grep -E "cov: .* ft: " $(FB)/fuzz_$$t.log | tail -1; \
	done

# replay the kept inputs (corpus and regress) under ASan + UBSan, no fuzzing
replay: $(BIN)
	@set -e; for t in $(FUZZ_TARGETS); do \
	  ASAN_OPTIONS=allocator_may_return_null=1 LSAN_OPTIONS=suppressions=$(CURDIR)/tests/sanitize/lsan.supp:print_suppressions=0 \
	  $(FB)/fuzz_$$t -runs=0 -timeout=20 -rss_limit_mb=2048 \
	    tests/fuzz/corpus/$$t $$(test -d tests/fuzz/regress/$$t && echo tests/fuzz/regress/$$t) \
	    >$(FB)/replay_$$t.log 2>&1 || { tail -40 $(FB)/replay_$$t.log; echo "1 passed, 1 failed"; exit 1; }; \
	  echo "ok - fuzz_$$t: $$(find tests/fuzz/corpus/$$t tests/fuzz/regress/$$t -type f 2>/dev/null | wc -l) inputs replayed under ASan+UBSan"; \
	done

all: $(BIN)

# with the headers each object read (-MMD): a changed header rebuilds them
# (an inline function moved into a header left stale objects unresolved)
$(FB)/%.o: libcommon/%.c
	@mkdir -p $(@D)
	$(FUZZ_CC) $(CPPFLAGS) $(CFLAGS) -MMD -MP -c -o $@ $<

$(FB)/%.o: libcommon/%.cpp
	@mkdir -p $(@D)
	$(FUZZ_CXX) $(CPPFLAGS) $(CXXFLAGS) -MMD -MP -c -o $@ $<

-include $(OBJ:.o=.d)

$(FB)/fuzz_%: tests/fuzz/fuzz_%.c tests/fuzz/fuzz_common.h $(OBJ)
	@mkdir -p $(@D)
	$(FUZZ_CXX) -x c $(CPPFLAGS) -O1 -g -std=c11 $(SAN) -fsanitize=fuzzer -c -o $@.o $<
	$(FUZZ_CXX) $(SAN) -fsanitize=fuzzer -pthread -o $@ $@.o $(OBJ) $(LDLIBS)

.PHONY: run all replay
.SECONDARY:
