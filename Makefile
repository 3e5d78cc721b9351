# Reproducible companion to Jimenez & Scheurle, "On some aspects of the discretization of the
# Suslov problem". `make check` runs the tests and the claims ledger; see README.md.
#
#   make            build build/suslov, the figure programs and the test programs
#   make check      unit tests + claims ledger (build/claims.tsv); last line "N passed, N failed"
#   make figures    every figure: figures/NAME.{pdf,png,txt} and data/NAME.csv
#   make bench      work-precision and per-step cost against GSL (data/bench.csv)
#   make paper      the companion text, paper/companion.pdf
#   make web        the annotated web edition, $(BUILD)/web/index.html (opens from disk);
#                   make check-web tests it in headless chromium; make web-deps installs its tools
#   make deps       install missing Debian packages (deps-check: only what make check needs)
#   make clean      remove $(BUILD); make distclean also removes every generated figure, data
#                   file, frame, video and PDF (not the committed PNG previews or data/animation.cfg)
#   WERROR=1        treat warnings as errors (CI)
#   SAN=1           build into build/san with -fsanitize=address,undefined,float-cast-overflow
#                   (added to any CFLAGS; float-cast-overflow is not part of undefined)

CC      ?= cc
BUILD   ?= build
CFLAGS  ?= -O2 -g
WARN    := -std=c17 -Wall -Wextra -Wshadow -Wstrict-prototypes
ifeq ($(WERROR),1)
WARN    += -Werror
endif
# The sanitizer flags live in their own variable, appended after CFLAGS/LDFLAGS, so that a
# command-line CFLAGS=... (which overrides any += here) cannot drop them.
SANFLAGS :=
ifeq ($(SAN),1)
BUILD   := build/san
SANFLAGS := -fsanitize=address,undefined,float-cast-overflow -fno-sanitize-recover=all -fno-omit-frame-pointer
endif
# Deferred (=) so that pkg-config runs after `deps` has installed the packages.
PKGS       = gsl cairo osmesa
PKG_CFLAGS = $(shell pkg-config --cflags $(PKGS))
PKG_LIBS   = $(shell pkg-config --libs $(PKGS))
ALL_CFLAGS = $(WARN) $(CFLAGS) $(SANFLAGS) -Isrc $(PKG_CFLAGS) -MMD -MP
ALL_LDFLAGS = $(LDFLAGS) $(SANFLAGS)

FIG_SRC  := $(wildcard src/figure_*.c)
FIGS     := $(FIG_SRC:src/figure_%.c=%)
FIG_BIN  := $(FIGS:%=$(BUILD)/figure_%)
LIB_SRC  := $(filter-out src/suslov.c src/bench.c src/animation.c $(FIG_SRC),$(wildcard src/*.c))
LIB_OBJ  := $(LIB_SRC:src/%.c=$(BUILD)/obj/%.o)
LIB      := $(BUILD)/libsuslov.a
TESTS    := $(patsubst tests/%.c,$(BUILD)/%,$(wildcard tests/test_*.c))
CLAIMS   := $(BUILD)/claims

.PHONY: all deps deps-check deps-figures deps-paper deps-bench check figures animation bench paper clean distclean
all: $(BUILD)/suslov $(BUILD)/bench $(BUILD)/animation $(FIG_BIN) $(TESTS) $(CLAIMS)

# What each goal needs (tools/deps.sh PROFILE): check = compiler, GSL, Cairo, OSMesa, fonts;
# figures adds ffmpeg; paper adds TeX. Objects wait only on deps-check.
deps: deps-paper deps-bench
deps-check deps-figures deps-paper:
	@sh tools/deps.sh $(@:deps-%=%)

$(BUILD)/obj/%.o: src/%.c | deps-check
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -c $< -o $@

$(BUILD)/tobj/%.o: tests/%.c | deps-check
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -Itests -c $< -o $@

$(LIB): $(LIB_OBJ)
	@rm -f $@
	$(AR) rcs $@ $^

$(BUILD)/suslov: $(BUILD)/obj/suslov.o $(LIB)
	$(CC) $(ALL_LDFLAGS) $^ $(PKG_LIBS) -lm -o $@

# A program that draws files depends on the objects it links, not on the whole archive: the
# linker's --trace given twice names the archive members it pulled, and $@.link.d makes the
# program depend on exactly those (a new reference can only come from a changed object already
# linked). The archive is order-only, so a change to an object the program does not link
# relinks nothing and redraws nothing. If the trace names no member (another linker), depend
# on the archive.
DRAW_PROGS := $(BUILD)/animation $(BUILD)/bench $(FIG_BIN)
$(DRAW_PROGS): $(BUILD)/%: $(BUILD)/obj/%.o | $(LIB)
	$(CC) $(ALL_LDFLAGS) $< $(LIB) $(PKG_LIBS) -lm -o $@ -Wl,--trace,--trace >$@.trace
	@objs=$$(sed -n -e 's|^(.*libsuslov\.a)\(.*\.o\)$$|$(BUILD)/obj/\1|p' \
	    -e 's|^.*libsuslov\.a(\(.*\.o\))$$|$(BUILD)/obj/\1|p' $@.trace | sort -u | tr '\n' ' '); \
	    echo "$@: $${objs:-$(LIB)}" >$@.link.d; rm -f $@.trace

$(TESTS): $(BUILD)/test_%: $(BUILD)/tobj/test_%.o $(LIB)
	$(CC) $(ALL_LDFLAGS) $^ $(PKG_LIBS) -lm -o $@

CLAIMS_OBJ := $(patsubst tests/%.c,$(BUILD)/tobj/%.o,$(wildcard tests/claims*.c) tests/ledger.c tests/expected_orders.c)
$(CLAIMS): $(CLAIMS_OBJ) $(LIB)
	$(CC) $(ALL_LDFLAGS) $^ $(PKG_LIBS) -lm -o $@

# A figure program writes its figure (PDF, PNG, caption) and its data together; it runs again
# only when the program (or anything it is linked from) changes.
figures: $(FIGS:%=figures/%.pdf) animation

# The attitude animation: frames, video (when ffmpeg is installed), filmstrip, caption and the
# R_k it draws.
animation: figures/attitude_filmstrip.png

figures/attitude_filmstrip.png figures/attitude.txt data/attitude.csv &: $(BUILD)/animation data/animation.cfg | deps-figures
	@mkdir -p figures data
	sh tools/timed.sh $(BUILD)/timings/animation.txt $< data/animation.cfg figures data

figures/%.pdf figures/%.png figures/%.txt data/%.csv: $(BUILD)/figure_% | deps-figures
	@mkdir -p figures data
	sh tools/timed.sh $(BUILD)/timings/figure_$*.txt $< figures data

check: all
	@SUSLOV_SAN=$(filter 1,$(SAN)) LSAN_OPTIONS=suppressions=$(CURDIR)/tests/lsan.supp:print_suppressions=0 \
	    sh tools/timed.sh $(BUILD)/timings/check.txt sh tests/run.sh $(BUILD)

# The fuzzer (tests/fuzz.c): random and hostile argument vectors against $(BUILD)/suslov for T
# seconds with the fixed seed SEED (printed, for replay), checking every promise of the
# interface; last line "fuzz: N passed, N failed". CI runs it under SAN=1.
T    ?= 60
SEED ?= 20261122
.PHONY: fuzz
fuzz: $(BUILD)/suslov $(BUILD)/fuzz
	@LSAN_OPTIONS=suppressions=$(CURDIR)/tests/lsan.supp:print_suppressions=0 $(BUILD)/fuzz $(BUILD)/suslov $(T) $(SEED)

$(BUILD)/fuzz: $(BUILD)/tobj/fuzz.o
	$(CC) $(ALL_LDFLAGS) $^ -o $@

# Speed and accuracy: data/bench.csv, figures/work_precision and figures/step_cost, and the
# PASS/MISS lines of the speed targets (never a failing test). make bench also times the
# Boost.Odeint peers: bench.c again with SUSLOV_WITH_ODEINT, linked with src/bench_odeint.cpp
# (g++ and the header-only Boost from `tools/deps.sh bench`, which make check never needs).
bench: all $(BUILD)/bench_boost
	@mkdir -p figures data
	@sh tools/timed.sh $(BUILD)/timings/bench.txt sh tools/bench.sh $(BUILD) "$(CFLAGS)"

CXXWARN := -std=c++17 -Wall -Wextra -Wshadow $(filter -Werror,$(WARN))
deps-bench:
	@sh tools/deps.sh bench
$(BUILD)/obj/bench_odeint.o: src/bench_odeint.cpp | deps-bench
	@mkdir -p $(@D)
	$(CXX) $(CXXWARN) $(CFLAGS) $(SANFLAGS) -Isrc -MMD -MP -c $< -o $@
$(BUILD)/obj/bench_boost.o: src/bench.c | deps-check
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -DSUSLOV_WITH_ODEINT -c $< -o $@
$(BUILD)/bench_boost: $(BUILD)/obj/bench_boost.o $(BUILD)/obj/bench_odeint.o $(LIB)
	$(CXX) $(ALL_LDFLAGS) $^ $(PKG_LIBS) -lm -o $@

# The companion text: every number from the claims ledger (build/numbers.tex) and the benchmark
# (data/bench.tex), figures from the figure programs, listings and equation map from src/.
$(BUILD)/claims.tsv $(BUILD)/numbers.tex $(BUILD)/ledger.tex $(BUILD)/summary.tex &: $(CLAIMS)
	$(CLAIMS) $(BUILD)/claims.tsv >/dev/null

# The same program as make bench (with the Boost.Odeint peers), so that the companion quotes
# the same comparison whichever of the two wrote data/bench.tex last.
data/bench.tex data/bench.csv figures/work_precision.pdf figures/step_cost.pdf &: $(BUILD)/bench_boost
	@mkdir -p figures data
	$< figures data >/dev/null

PAPER_IN := paper/companion.tex paper/equations.txt paper/labels.tsv $(BUILD)/numbers.tex $(BUILD)/ledger.tex \
            $(BUILD)/summary.tex data/bench.tex \
            $(FIGS:%=figures/%.pdf) figures/work_precision.pdf figures/attitude_filmstrip.png \
            $(wildcard src/*.c src/*.h) tools/paper.sh tools/snippet.sh tools/eqmap.sh \
            tools/paper_numbers.sh tools/paper_refs.sh tools/repro.sh tools/figsplit.sh
paper: paper/companion.pdf

paper/companion.pdf: $(PAPER_IN) | deps-paper
	@sh tools/paper.sh $(BUILD)

# The web edition (tools/web/): a static site, one side-by-side page per source file, the
# equations, the ledger and the figures, rebuilt when any of them changes. Its tools (Debian's
# python3-markdown, pygments, universal-ctags, chromium; KaTeX and playwright-core from npm) come
# from make web-deps, which make check never needs. /usr/bin/python3 is Debian's, the one with
# python3-markdown. The paper's LaTeX is read only when paper/labels.tsv is missing. The figures
# page shows what make figures and make bench have written; it never draws them: the figure
# files are not prerequisites (their rules would run the programs), a listing of their names and
# times is, with the names in src/ and tests/ so that a removed file also rebuilds the site
# ($(WEB)/inputs.list, rewritten only when it changes).
WEB       := $(BUILD)/web
WEB_PY    := /usr/bin/python3
PAPER_TEX ?= ../shared/seeds/000_7d469b10bebd47d3.txt
WEB_IN    := $(wildcard src/*.c src/*.h tests/*.c tests/*.sh) paper/equations.txt $(wildcard paper/labels.tsv) \
             $(BUILD)/claims.tsv $(WEB)/inputs.list \
             $(wildcard tools/web/*.py tools/web/*.tex tools/web/*.tsv tools/web/*.css) tools/web/package-lock.json
.PHONY: web web-deps check-web FORCE
web: $(WEB)/index.html

$(WEB)/index.html: $(WEB_IN) | web-deps
	$(WEB_PY) tools/web/build.py --out $(WEB) --claims $(BUILD)/claims.tsv --paper $(PAPER_TEX)

$(WEB)/inputs.list: FORCE
	@mkdir -p $(@D)
	@{ ls -l --time-style=+%s figures/*.png figures/*.txt data/*.csv; ls src tests; } >$@.tmp 2>/dev/null || true
	@if cmp -s $@.tmp $@; then rm -f $@.tmp; else mv $@.tmp $@; fi

web-deps:
	@sh tools/web/deps.sh

# Every page in headless chromium: links, math, no network, the (taudyn) page and its screenshot
# ($(WEB)/shots/taudyn.png). Last line "check-web: N passed, N failed".
check-web: web
	node tools/web/check_web.js $(WEB) paper/equations.txt $(BUILD)/claims.tsv

# The mutation check: each one-line mutant of tests/mutants is applied to a scratch copy of the
# tree, which is rebuilt and tested; every mutant must be killed (tools/mutants.sh). CI runs
# the fixed subset MUTANTS_STRIDE=k: mutants 1, 1+k, 1+2k, ...
.PHONY: mutants
mutants: | deps-check
	@sh tools/mutants.sh tests/mutants $(MUTANTS_STRIDE)

# The generated operator-mutation campaign (tools/mutants_ops.py): every floating literal scaled,
# + <-> -, * <-> /, array index +-1, comparison negated, over the library files in priority order;
# last line "mutants-ops: generated N, killed K, equivalent E, survived S, did-not-build B, score X".
# MUTANTS_OPS_SAMPLE=N runs a seeded sample of N (seed MUTANTS_OPS_SEED; CI), MUTANTS_OPS_FILES
# a subset of the files; the full campaign writes tests/mutants_ops_result.txt with its commit.
MUTANTS_OPS_SAMPLE ?= 0
MUTANTS_OPS_SEED   ?= 20261123
MUTANTS_OPS_OUT    ?= $(if $(filter 0,$(MUTANTS_OPS_SAMPLE)),tests/mutants_ops_result.txt,$(BUILD)/mutants_ops_sample.txt)
.PHONY: mutants-ops deps-mutants
deps-mutants:
	@sh tools/deps.sh mutants
mutants-ops: | deps-mutants
	@mkdir -p $(BUILD)
	@python3 tools/mutants_ops.py --sample $(MUTANTS_OPS_SAMPLE) --seed $(MUTANTS_OPS_SEED) \
	    --out $(MUTANTS_OPS_OUT) $(if $(MUTANTS_OPS_FILES),--files $(MUTANTS_OPS_FILES))

clean:
	rm -rf $(BUILD)

# Everything `make figures`, `make bench` and `make paper` write; the PNG previews the README
# shows and data/animation.cfg are committed sources of a fresh clone and stay (in a git
# checkout, a PNG that git does not track goes too).
distclean: clean
	rm -rf figures/*.pdf figures/*.txt figures/*.tmp.* figures/attitude figures/attitude.mp4 \
	    data/*.csv data/*.tex data/*.tmp.* paper/companion.pdf paper/*.tmp
	@if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then \
	    for f in figures/*.png; do \
	        [ ! -e "$$f" ] || git ls-files --error-unmatch "$$f" >/dev/null 2>&1 || { echo "rm -f $$f"; rm -f "$$f"; }; \
	    done; \
	fi

-include $(wildcard $(BUILD)/obj/*.d $(BUILD)/tobj/*.d $(BUILD)/*.link.d)
