# aeroeval — multirotor UAV sizing compiler.
#
# Read top to bottom: settings, flags, the library every program links,
# the programs, the tests, then the housekeeping targets.
#
#   make example   install missing Debian packages, build, compile examples/ into out/
#   make test      install missing Debian packages, build, run every test
#   make install   PREFIX=/usr/local DESTDIR= honoured

# ---- settings ---------------------------------------------------------------
PREFIX   ?= /usr/local
DESTDIR  ?=
BUILD    ?= build
ASAN     ?= build-asan
CC       ?= cc
VERSION  := 0.1.0
# Parallel jobs of `make test` (its builds and its test programs).
JOBS     ?= $(shell nproc 2>/dev/null || echo 2)

# What the build, the tests and the examples need, each with the Debian
# package that gives it.  `deps` finds libraries with pkg-config, libharu
# (which ships no .pc file) by compiling against it, tools with command -v
# and files by their path, then installs only the packages of what is
# missing, so a machine that has everything never needs root.
DEP_PKGCONFIG := libcjson=libcjson-dev cairo=libcairo2-dev libcrypto=libssl-dev \
                 cmocka=libcmocka-dev
DEP_HPDF      := libhpdf-dev
DEP_TOOLS     := $(firstword $(CC))=gcc pkg-config=pkg-config pdftotext=poppler-utils
DEP_FILES     := /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf=fonts-dejavu-core

# ---- flags ------------------------------------------------------------------
# CPPFLAGS, CFLAGS, LDFLAGS and LDLIBS from the command line or the
# environment are honoured: they come after the project's own, so they can
# override them.  pkg-config runs when the Makefile is read; `make test` and
# `make example` read it again (a sub-make) after `deps` has installed it.
PKGS       := cairo libcjson libcrypto
PKG_CFLAGS := $(shell pkg-config --cflags $(PKGS) 2>/dev/null)
PKG_LIBS   := $(shell pkg-config --libs $(PKGS) 2>/dev/null) -lhpdf -lm
TEST_LIBS  := $(shell pkg-config --libs cmocka 2>/dev/null)
# The test programs link with gold where binutils has it (it comes with
# gcc on Debian): 0.12 s a link against bfd's 0.28 s, some 60 links in a
# fresh `make test`.  The program itself keeps the default linker; LDFLAGS
# comes after, so a linker chosen there wins.
TEST_LD    := $(shell command -v ld.gold >/dev/null 2>&1 && echo -fuse-ld=gold)

WARN := -Wall
WARN += -Wextra
WARN += -Wshadow
WARN += -Wstrict-prototypes
WARN += -Wmissing-prototypes
WARN += -Wwrite-strings
WARN += -Wundef
WARN += -Wformat=2
WARN += -Wvla
WARN += -Werror

# The debug information names source files relative to the tree, so two
# checkouts of one commit, wherever they are, build identical binaries.
OPT         ?= -O2 -g
AE_CPPFLAGS := -D_DEFAULT_SOURCE -DAEROEVAL_VERSION='"$(VERSION)"' -Isrc
AE_CFLAGS    = -std=c11 $(OPT) $(WARN) -ffile-prefix-map=$(CURDIR)=.
COMPILE      = $(CC) $(AE_CPPFLAGS) $(CPPFLAGS) $(AE_CFLAGS) $(PKG_CFLAGS) $(CFLAGS)
LINK         = $(CC) $(AE_CFLAGS) $(CFLAGS) $(LDFLAGS)

# ---- the library ------------------------------------------------------------
# Every src/LAYER/*.c except cli/main.c goes into libaeroeval.a, which the
# program and every test link.  The folders are the layers, lowest first
# (docs/architecture.md): util; the plain values the layers above share
# (diag, spec, catalog, template, result); the engine (physics, sizing,
# parts, engine); the files read (input); the files written: their text
# (formats), atomic files and folders (fs), the PDF documents (pdf); the
# studies (study); cli; and tools, the build-time programs (catsnap), on
# top.  `make check-layers` (part of `make test`) keeps every include
# pointing down this list.  The programs' own sources (cli/main.c, tools/)
# stay out of the library.
LAYERS   := util diag spec catalog template result physics sizing parts engine \
            input formats fs pdf study cli tools
LIB_SRCS := $(filter-out src/cli/main.c src/tools/%.c,$(foreach l,$(LAYERS),$(wildcard src/$(l)/*.c)))
LIB_OBJS := $(LIB_SRCS:src/%.c=$(BUILD)/obj/%.o)
LIB      := $(BUILD)/libaeroeval.a
BIN      := $(BUILD)/aeroeval

# The test build.  Test hooks (AEROEVAL_FAIL_ALLOC, AEROEVAL_FAIL_WRITE,
# AEROEVAL_TEST_*: faults and delays injected from the environment) are
# compiled only with -DAEROEVAL_TEST_HOOKS: the program `make` builds and
# installs has none.  The few sources that hold a hook (or include a header
# that does) are compiled a second time with it, into obj-hooks/; the test
# library is the library with those objects swapped in, and aeroeval-test
# the program over it, which the whole-compiler tests run.  A file holds a
# hook when a preprocessor condition names the macro (HOOK_IF: the "#" of
# the directive is any punctuation here, a "#" would start a make comment
# in older makes); one that only mentions it in a comment is compiled once.
HOOK_IF   := '^[[:space:]]*[[:punct:]][[:space:]]*(if|ifdef|ifndef|elif)[[:space:]].*AEROEVAL_TEST_HOOKS'
HOOK_HDRS := $(shell grep -lE $(HOOK_IF) src/*/*.h)
HOOK_SRCS := $(shell grep -lE -e $(HOOK_IF) $(foreach h,$(HOOK_HDRS),-e '$(notdir $(h))') $(LIB_SRCS))
HOOK_OBJS := $(HOOK_SRCS:src/%.c=$(BUILD)/obj-hooks/%.o)
TEST_LIB  := $(BUILD)/libaeroeval-test.a
TEST_BIN  := $(BUILD)/aeroeval-test

TEST_SRCS := $(wildcard tests/test_*.c)
TEST_BINS := $(TEST_SRCS:tests/%.c=$(BUILD)/tests/%)

.PHONY: all deps test unit example paper install clean check-layers asan \
        asan-build fuzz bench closure golden fonts

all: $(BIN) aeroeval

# The program is built out of tree; ./aeroeval is a convenience link.
aeroeval: $(BIN)
	ln -sf $(BIN) aeroeval

deps:
	@missing=""; \
	for d in $(DEP_TOOLS); do \
	  command -v "$${d%%=*}" >/dev/null 2>&1 || missing="$$missing $${d#*=}"; \
	done; \
	for d in $(DEP_FILES); do [ -f "$${d%%=*}" ] || missing="$$missing $${d#*=}"; done; \
	for d in $(DEP_PKGCONFIG); do \
	  pkg-config --exists "$${d%%=*}" 2>/dev/null || missing="$$missing $${d#*=}"; \
	done; \
	if [ -n "$(DEP_HPDF)" ]; then \
	  t=$$(mktemp -d); \
	  printf '#include <hpdf.h>\nint main(void) { return HPDF_GetVersion() == 0; }\n' >$$t/h.c; \
	  $(CC) $$t/h.c -o $$t/h -lhpdf >/dev/null 2>&1 || missing="$$missing $(DEP_HPDF)"; \
	  rm -rf $$t; \
	fi; \
	if [ -n "$$missing" ]; then \
	  echo "deps: installing$$missing"; \
	  SUDO=""; [ "$$(id -u)" -ne 0 ] && SUDO=sudo; \
	  $$SUDO apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -qq --no-install-recommends $$missing; \
	fi

$(BUILD)/obj/%.o: src/%.c
	@mkdir -p $(@D)
	$(COMPILE) -MMD -MP -c $< -o $@

$(BUILD)/obj-hooks/%.o: src/%.c
	@mkdir -p $(@D)
	$(COMPILE) -DAEROEVAL_TEST_HOOKS -MMD -MP -c $< -o $@

$(LIB): $(LIB_OBJS)
	rm -f $@
	ar rcs $@ $^

$(TEST_LIB): $(filter-out $(HOOK_SRCS:src/%.c=$(BUILD)/obj/%.o),$(LIB_OBJS)) $(HOOK_OBJS)
	rm -f $@
	ar rcs $@ $^

$(BIN): $(BUILD)/obj/cli/main.o $(BUILD)/obj/cli/snapshot.o $(LIB)
	$(LINK) -o $@ $^ $(PKG_LIBS) $(LDLIBS)

$(TEST_BIN): $(BUILD)/obj/cli/main.o $(BUILD)/obj/cli/snapshot.o $(TEST_LIB)
	$(LINK) -o $@ $^ $(PKG_LIBS) $(LDLIBS)

# The shipped catalogue, loaded and checked once here and carried inside the
# program (src/input/catalog_snap.h): catsnap (src/tools/) writes the
# snapshot, and snapshot.S includes its bytes.  At start-up aeroeval uses it
# only when the catalogue files hold exactly the bytes it was made from,
# else it reads their JSON.
CATALOG_FILES := $(wildcard data/catalog/*.json) data/chemistries.json
SNAP          := $(BUILD)/gen/catalog.snap

$(BUILD)/catsnap: $(BUILD)/obj/tools/catsnap.o $(LIB)
	$(LINK) -o $@ $^ $(PKG_LIBS) $(LDLIBS)

$(SNAP): $(BUILD)/catsnap $(CATALOG_FILES)
	@mkdir -p $(@D)
	$(BUILD)/catsnap data $@

$(BUILD)/obj/cli/snapshot.o: src/cli/snapshot.S $(SNAP)
	@mkdir -p $(@D)
	$(CC) -c -I$(BUILD)/gen -o $@ $<

# TEST_OPT (after OPT, so it wins) compiles the test sources themselves.
# The test programs carry the catalogue snapshot too: those that load the
# shipped catalogue then skip its parse (half a second each under ASan).
$(BUILD)/tests/%: tests/%.c $(BUILD)/obj/cli/snapshot.o $(TEST_LIB) | $(BUILD)/tests
	$(COMPILE) $(TEST_OPT) -DAEROEVAL_TEST_HOOKS -Itests -MMD -MP -o $@ $< $(TEST_LD) \
	  $(LDFLAGS) $(BUILD)/obj/cli/snapshot.o $(TEST_LIB) $(PKG_LIBS) $(TEST_LIBS) $(LDLIBS)

$(BUILD)/tests:
	mkdir -p $@

-include $(wildcard $(BUILD)/obj/*/*.d $(BUILD)/obj-hooks/*/*.d $(BUILD)/tests/*.d)

# ---- tests ------------------------------------------------------------------
# `make test` builds, $(JOBS) jobs at once, the program and its test build
# (aeroeval-test) in $(BUILD)/, with the random-mission sweep and the
# monotonicity test as they ship (-O2, where they run their full counts:
# 1000 and 500 missions) and the two unit programs whose dossiers the
# scripts read.  tests/run_all.sh then runs the whole-compiler scripts
# (tests/cli_*.sh, on aeroeval-test), the checks (tests/check_*.sh), that
# sweep and that test, one more than $(JOBS) at a time, while the unit
# programs (one cmocka program per module) are built under AddressSanitizer
# + UndefinedBehaviorSanitizer in $(ASAN)/; they run as soon as that build
# ends.  It closes with one line "N passed, N failed".  `make unit` builds
# and runs the unit programs without the sanitizers, `make asan` with them.
# The unit programs built as they ship: the sweep, the monotonicity test,
# and the two whose dossiers tests/cli_doc.sh and tests/cli_report.sh read.
SCRIPT_UNITS := $(BUILD)/tests/test_sweep $(BUILD)/tests/test_monotone \
  $(BUILD)/tests/test_doc $(BUILD)/tests/test_report

# The tests run one more at a time than there are jobs: several scripts
# spend part of their time waiting (a slowed write, a worker's time-out),
# and the extra one takes up that slack.
test: deps
	@$(MAKE) --no-print-directory -j$(JOBS) all $(TEST_BIN) $(SCRIPT_UNITS)
	@sh tests/run_all.sh -j $$(($(JOBS) + 1)) --scripts $(BUILD) \
	  --meanwhile '$(MAKE) --no-print-directory -j$(JOBS) asan-build' $(ASAN) \
	  $(BUILD)/tests/test_sweep $(BUILD)/tests/test_monotone $(ASAN)

unit: $(TEST_BINS)
	sh tests/run_all.sh -j $(JOBS) $(BUILD)

# ---- robustness: sanitizers, fuzzing, benchmarks ---------------------------
# `asan` builds the test library and the unit programs in $(ASAN)/ under
# ASan+UBSan (UB aborts the test) and runs them; `make test` runs them beside
# the normal ones.  OPT reaches the link too (the link uses AE_CFLAGS).
# -g1: line tables and functions, all a sanitizer's report needs, and
# quicker to compile than full debug information.
SAN_OPT := -O1 -g1 -fsanitize=address,undefined -fno-omit-frame-pointer \
           -fno-sanitize-recover=undefined
# The test sources there are compiled without optimisation (half the
# compile time; what they run is the library, at -O1).
asan-build:
	@$(MAKE) --no-print-directory BUILD=$(ASAN) OPT='$(SAN_OPT)' TEST_OPT='-O0' \
	  $(TEST_BINS:$(BUILD)/%=$(ASAN)/%)

asan: asan-build
	sh tests/run_all.sh -j $(JOBS) $(ASAN)

# `fuzz` (not part of `make test`) builds the libFuzzer harnesses
# tests/fuzz/fuzz_*.c with clang and runs each for FUZZ_SECONDS from the seed
# corpus; a crash lands in build-fuzz/fuzz/NAME/ (keep it in tests/regress/).
# The library is rebuilt with clang there, warnings not fatal (clang's
# warning set differs from gcc's, which `make all` holds to -Werror).
FUZZ_CC      ?= clang-14
FUZZ_SECONDS ?= 30
FUZZ_SAN     := address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer
FUZZ_FLAGS   := -std=c11 -O1 -g -fsanitize=fuzzer,$(FUZZ_SAN)
fuzz: deps
	$(MAKE) -s CC=$(FUZZ_CC) BUILD=build-fuzz WARN=-Wall \
	  OPT='-O1 -g -fsanitize=fuzzer-no-link,$(FUZZ_SAN)' build-fuzz/libaeroeval.a
	sh tests/fuzz/run.sh build-fuzz $(FUZZ_CC) '$(FUZZ_FLAGS)' $(FUZZ_SECONDS)

# `bench` (not part of `make test`): instructions per command, the batch's
# wall time and memory, each beside its target (tests/bench.sh).
bench: all $(BUILD)/bench
	sh tests/bench.sh $(BUILD)

# `closure`: the closure reports alone (also the first part of `bench`):
# 200 plausible missions from each of seeds 1-3, the share that closes on
# real parts and the closed-vs-continuous takeoff-mass gap; then the
# missions the calibration cohort's real aircraft fly (docs/performance.md).
closure: all $(BUILD)/bench
	$(BUILD)/bench closure 1-3 200 $(BIN) data/catalog
	$(BUILD)/bench aircraft data/cohorts/calibration.csv data/catalog

$(BUILD)/bench: tests/bench.c $(LIB)
	$(COMPILE) -Itests -o $@ $< $(LDFLAGS) $(LIB) $(PKG_LIBS) $(LDLIBS)

# ---- examples ---------------------------------------------------------------
# Exit status 1 means "compiled, some design infeasible": the outputs are
# written and say why, so it does not fail the target.
example: deps
	$(MAKE) all
	./$(BIN) build -o out examples/ || [ $$? -eq 1 ]

# ---- golden outputs ---------------------------------------------------------
# Rewrites tests/golden/ from the examples (result.json, bom.csv, dossier
# text); `make test` compares against it.  Commit the diff with the reason.
golden: all
	AEROEVAL=$(BIN) sh tests/cli_golden.sh update

# ---- fonts ------------------------------------------------------------------
# `fonts` (not part of the build: its output is committed) regenerates
# templates/fonts/: Debian's DejaVu Sans, Sans Bold and Sans Mono cut by
# fonttools' pyftsubset, with DejaVu's licence beside them.  libharu parses
# the whole font file for each document and then maps every UTF-8 code point
# (63 000) through the font's cmap by a linear walk over its segments (runs
# of consecutive characters), so the cost of a font is its glyph count plus
# 63 000 x its segment count: the whole DejaVu Sans has ~6000 glyphs in 242
# segments, the cut one ~830 in 14.
# FONT_CHARS (Sans, Sans Bold) is every character the dossier's own text
# uses (the non-ASCII ones in src/ string literals: ° ± ² · × Ø ÷ γ η λ – — •
# … → − ≈ ≤ ≥) plus a margin for the text users bring (titles, clients,
# catalogue names, template titles): all of Latin-1 and Latin Extended-A,
# the Greek and basic Cyrillic alphabets, the punctuation U+2010-203A
# (dashes, quotes ‘ ’ “ ”, • … ‰ ′ ″), super- and subscript digits, € and ™,
# the arrows ← ↑ → ↓ ↔ ↕ and the mathematical operators U+2200-22FF, chosen
# as whole runs (a run costs one segment, a scattered character one each).
# Nothing above U+22FF (not even U+FFFD): the document's glyph map holds two
# bytes for every code up to the highest one the font has (doc.c cuts
# libharu's 128 KiB map there), so U+22FF keeps it at 18 KiB a font; a code
# the font lacks, U+FFFD included, prints as the .notdef box.
# FONT_CHARS_MONO is for what the dossier sets in Sans Mono: fingerprints and
# catalogue ids (lowercase slugs), so ASCII and Latin-1.  A character outside
# the set prints as the .notdef box (as CJK did with the whole font) and stays
# searchable.  After changing a set: `make fonts`, `make test`, commit
# templates/fonts/.
FONT_SRC        := /usr/share/fonts/truetype/dejavu
FONT_CHARS      := U+0020-007E,U+00A0-017F,U+0391-03A1,U+03A3-03C9,U+0400-045F, \
                   U+2010-203A,U+2070-2071,U+2074-208E,U+20AC,U+2122,U+2190-2195, \
                   U+2200-22FF
FONT_CHARS_MONO := U+0020-007E,U+00A0-00FF
FONT_SUBSET      = pyftsubset $(FONT_SRC)/$(1).ttf --unicodes='$(2)' \
                   --output-file=templates/fonts/$(1).ttf --layout-features='' \
                   --drop-tables+=GSUB,GPOS,GDEF,MATH,FFTM --name-IDs='*' \
                   --notdef-outline
fonts:
	@$(MAKE) --no-print-directory deps DEP_PKGCONFIG= DEP_HPDF= \
	  DEP_TOOLS=pyftsubset=fonttools
	mkdir -p templates/fonts
	$(call FONT_SUBSET,DejaVuSans,$(FONT_CHARS))
	$(call FONT_SUBSET,DejaVuSans-Bold,$(FONT_CHARS))
	$(call FONT_SUBSET,DejaVuSansMono,$(FONT_CHARS_MONO))
	cp /usr/share/doc/fonts-dejavu-core/copyright templates/fonts/LICENSE

# ---- the paper's studies ----------------------------------------------------
# Case studies, shedding and the 14-parameter sensitivity, ours beside the paper's.
paper: all
	sh tests/paper.sh $(BUILD)

# ---- housekeeping -----------------------------------------------------------
# The man page's header carries the version; it is set from VERSION here.
install: all
	install -d $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(PREFIX)/share/aeroeval \
	  $(DESTDIR)$(PREFIX)/share/man/man1
	install -m 755 $(BIN) $(DESTDIR)$(PREFIX)/bin/aeroeval
	cp -R data templates $(DESTDIR)$(PREFIX)/share/aeroeval/
	sed '/^\.TH/s/"aeroeval [^"]*"/"aeroeval $(VERSION)"/' src/cli/aeroeval.1 \
	  >$(DESTDIR)$(PREFIX)/share/man/man1/aeroeval.1
	chmod 644 $(DESTDIR)$(PREFIX)/share/man/man1/aeroeval.1

# The folders of src/ are layers, in the order of LAYERS: includes point
# down, physics sees no I/O, no circle of includes or of calls
# (tests/check_layers.sh; `make test` runs it too).
check-layers:
	sh tests/check_layers.sh

clean:
	rm -rf $(BUILD) $(ASAN) aeroeval
