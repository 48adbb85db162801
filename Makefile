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
CC       ?= cc
VERSION  := 0.1.0

# Debian packages the build, the tests and the examples need.  `deps` installs
# only the ones missing, so a machine that has them never needs root.
DEB_PKGS := gcc make pkg-config libcjson-dev libhpdf-dev libcairo2-dev \
            libssl-dev libfontconfig-dev libcmocka-dev fonts-dejavu-core poppler-utils

# ---- flags ------------------------------------------------------------------
# Recursively expanded on purpose: pkg-config runs when a recipe needs the
# flags, i.e. after `deps` has installed it on a fresh machine.
PKG_CFLAGS = $(shell pkg-config --cflags cairo libcjson libcrypto fontconfig 2>/dev/null)
PKG_LIBS   = $(shell pkg-config --libs cairo libcjson libcrypto fontconfig 2>/dev/null) -lhpdf -lm

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
OPT      ?= -O2 -g
CFLAGS   += -std=c11 $(OPT) $(WARN) -ffile-prefix-map=$(CURDIR)=.
CPPFLAGS += -D_DEFAULT_SOURCE -DAEROEVAL_VERSION='"$(VERSION)"' -Isrc

# ---- the library ------------------------------------------------------------
# Every src/LAYER/*.c except cli/main.c goes into libaeroeval.a, which the
# program and every test link.  The folders are the layers, lowest first:
# util, core, physics, sizing, parts, engine, then study, input and output
# side by side, and cli on top (docs/architecture.md); `make check-layers`
# (part of `make test`) keeps every include pointing down.
LAYERS   := util core physics sizing parts engine study input output cli
LIB_SRCS := $(filter-out src/cli/main.c,$(foreach l,$(LAYERS),$(wildcard src/$(l)/*.c)))
LIB_OBJS := $(LIB_SRCS:src/%.c=$(BUILD)/obj/%.o)
LIB      := $(BUILD)/libaeroeval.a
BIN      := $(BUILD)/aeroeval

TEST_SRCS := $(wildcard tests/test_*.c)
TEST_BINS := $(TEST_SRCS:tests/%.c=$(BUILD)/tests/%)

.PHONY: all deps test unit example paper install clean check-layers asan fuzz bench closure golden fonts

all: $(BIN) aeroeval

# The program is built out of tree; ./aeroeval is a convenience link.
aeroeval: $(BIN)
	ln -sf $(BIN) aeroeval

deps:
	@missing=""; for p in $(DEB_PKGS) $(EXTRA_PKGS); do \
	  dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q 'ok installed' || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then \
	  echo "deps: installing$$missing"; \
	  SUDO=""; [ "$$(id -u)" -ne 0 ] && SUDO=sudo; \
	  $$SUDO apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -qq --no-install-recommends $$missing; \
	fi

$(BUILD)/obj/%.o: src/%.c
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) $(CFLAGS) $(PKG_CFLAGS) -MMD -MP -c $< -o $@

$(LIB): $(LIB_OBJS)
	rm -f $@
	ar rcs $@ $^

$(BIN): $(BUILD)/obj/cli/main.o $(LIB)
	$(CC) $(CFLAGS) -o $@ $^ $(PKG_LIBS)

$(BUILD)/tests/%: tests/%.c $(LIB) | $(BUILD)/tests
	$(CC) $(CPPFLAGS) $(CFLAGS) $(PKG_CFLAGS) -Itests -MMD -MP -o $@ $< $(LIB) $(PKG_LIBS) -lcmocka

$(BUILD)/tests:
	mkdir -p $@

-include $(wildcard $(BUILD)/obj/*/*.d $(BUILD)/tests/*.d)

# ---- tests ------------------------------------------------------------------
# Unit tests (one cmocka program per module) then the whole-compiler tests
# (tests/cli_*.sh); tests/run_all.sh prints one closing "N passed, N failed".
test: deps
	$(MAKE) all $(TEST_BINS)
	sh tests/run_all.sh $(BUILD)
	@$(MAKE) --no-print-directory asan

unit: $(TEST_BINS)
	sh tests/run_all.sh $(BUILD) unit

# ---- robustness: sanitizers, fuzzing, benchmarks ---------------------------
# `asan` rebuilds everything in build-asan/ under ASan+UBSan (UB aborts the
# test) and runs the unit suite there; `make test` runs it after the normal
# suite.  OPT reaches the link too (the link rules use $(CFLAGS)).
SAN_OPT := -O1 -g -fsanitize=address,undefined -fno-omit-frame-pointer \
           -fno-sanitize-recover=undefined
asan:
	@echo "== the unit suite again, under ASan+UBSan (build-asan/)"
	@$(MAKE) --no-print-directory BUILD=build-asan OPT='$(SAN_OPT)' unit

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
	$(CC) $(CPPFLAGS) $(CFLAGS) $(PKG_CFLAGS) -Itests -o $@ $< $(LIB) $(PKG_LIBS)

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
	@$(MAKE) --no-print-directory deps DEB_PKGS= EXTRA_PKGS='fonttools fonts-dejavu-core'
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

# The folders of src/ are layers: includes point down, physics sees no I/O,
# no module cycles (tests/check_layers.sh; `make test` runs it too).
check-layers:
	sh tests/check_layers.sh

clean:
	rm -rf $(BUILD) aeroeval
