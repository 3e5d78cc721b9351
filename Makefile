# Reproducible companion to Jimenez & Scheurle, "On some aspects of the discretization of the
# Suslov problem". `make check` runs the tests and the claims ledger; see README.md, and
# docs/reference/make-targets.md, which quotes the lines below (tools/readme_make.sh).
#
#   make            build build/suslov, the figure programs and the test programs
#   make test       unit, CLI and build tests (seconds); make ledger: the claims ledger
#   make check      both: tests + claims ledger (build/claims.tsv); last line "N passed, N failed"
#   make ledger-inproc  the ledger in one process, the same bytes as make check's (CI runs it)
#   make figures    every figure: figures/NAME.{pdf,png,txt} and data/NAME.csv, and the animation
#   make animation  the animation alone: figures/attitude.mp4, figures/attitude/, the filmstrip
#   make bench      work-precision and per-step cost against GSL and Boost: a fresh run in
#                   data/bench-run/ (summary.md, bench.csv, ...), its figures in $(BUILD)/bench-run/
#   make bench-record  the same, into data/bench-recorded/ (the run the companion and the docs
#                   quote, committed with its machine.txt), and the previews drawn from it
#   make paper      the companion text, paper/companion.pdf and paper/methods.pdf (committed,
#                   byte for byte reproducible; make check fails when their numbers are stale);
#                   PAPER_BASE=URL/ makes its code links absolute
#   make web        the annotated web edition, $(BUILD)/web/index.html (opens from disk);
#                   make check-web tests it in headless chromium; make web-deps installs its tools;
#                   make web-shots takes screenshots; PAPER_TEX=FILE is the paper's LaTeX source
#   make deps       install missing Debian packages (make check installs only what it needs)
#   make install    PREFIX=DIR (default /usr/local): suslov, its manual page, libsuslov.a, the
#                   public headers (include/suslov/suslov.h) and suslov.pc for pkg-config;
#                   make uninstall PREFIX=DIR removes them
#   make fuzz       hostile argument vectors against suslov for T seconds (default 60), seed SEED
#   make mutants    the hand-listed mutants of tests/build/mutants, each one must fail a test
#                   (MUTANTS_STRIDE=k: every k-th); make mutants-ops: the generated campaign (hours)
#   make clean      remove $(BUILD); make distclean also removes every generated figure, data
#                   file, frame, video and PDF (not the committed PNG previews or data/animation.cfg)
#   BUILD=DIR       the build directory (default build)
#   V=1             print every command in full (default: one short line per step, "  CC  FILE")
#   WERROR=1        treat warnings as errors (CI)
#   SAN=1           build into build/san with -fsanitize=address,undefined,float-cast-overflow
#                   (added to any CFLAGS; float-cast-overflow is not part of undefined)

# `make` alone is `make all`: the stamp rules below come first and would otherwise be the goal.
.DEFAULT_GOAL := all
# Every rule is written here: make's search of its built-in rules for each file would be a third
# of the time of every make, and the tests run make dozens of times.
MAKEFLAGS += --no-builtin-rules
.SUFFIXES:
# Output for people: one short line per step, as the Linux kernel's build prints it
# ("  CC      src/core/model.c"), and the commands themselves with V=1. make -s prints neither.
# A recipe line is $(call say,WHAT,FILE) followed by the command prefixed with $(Q).
V ?= 0
ifeq ($(V),1)
Q   :=
say  = @:
else
Q   := @
say  = @printf '  %-7s %s\n' $(call sq,$(1)) $(call sq,$(2))
endif
ifneq ($(findstring s,$(firstword -$(MAKEFLAGS))),)
say  = @:
endif
CC      ?= cc
BUILD   ?= build
# An empty BUILD= would write to /obj and /suslov; a BUILD with a space breaks make's own lists.
ifeq ($(strip $(BUILD)),)
$(error BUILD is empty: give a directory, e.g. BUILD=build)
endif
ifneq ($(words $(BUILD)),1)
$(error BUILD='$(BUILD)' holds a space: make cannot name targets inside it)
endif
# Every function starts on a 64-byte boundary, the width of the fetch and micro-op cache windows:
# a hot loop's timing then depends on its own code, not on how much code the linker placed
# before it, which otherwise moves the bench's tightest loops from one build to the next.
CFLAGS  ?= -O2 -g -falign-functions=64
WARN    := -std=c17 -Wall -Wextra -Wshadow -Wstrict-prototypes
# The same bits in every build (the CLI and the browser's WebAssembly module): no product and
# sum fused into one fma, which a compiler may otherwise do where the target has one.
WARN    += -ffp-contract=off
# clang reports an unroll hint (#pragma GCC unroll) that its optimizer could not follow as a
# warning: a note about speed, not about the code, so it does not fail a WERROR=1 build.
ifneq ($(findstring clang,$(shell $(CC) --version 2>/dev/null | head -1)),)
WARN    += -Wno-pass-failed
endif
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
# Deferred (=) so that pkg-config runs after `deps` has installed the packages, and then once: the
# first use replaces each with its value (a make -n plans ~100 recipes, and a process costs
# milliseconds on a small VM). A program links
# only what it uses: suslov, the claims ledger and most unit tests GSL and libm (LIBS_RUN); the
# programs that draw (figures, animation, bench, and the unit tests that include a header of
# src/render) also Cairo and OSMesa (LIBS_DRAW). A linker that keeps every library it is given
# (clang's default) would otherwise map Cairo, OSMesa and LLVM into suslov.
PKGS       = gsl cairo osmesa libpng
PKG_CFLAGS = $(eval PKG_CFLAGS := $$(shell pkg-config --cflags $$(PKGS)))$(PKG_CFLAGS)
LIBS_RUN   = $(eval LIBS_RUN := $$(shell pkg-config --libs gsl) -lm)$(LIBS_RUN)
LIBS_DRAW  = $(eval LIBS_DRAW := $$(shell pkg-config --libs $$(PKGS)) -lm)$(LIBS_DRAW)
ALL_LDFLAGS = $(LDFLAGS) $(SANFLAGS)

# The layers of src/, lowest first (tests/build/layers.sh checks the order). Each layer is
# compiled with only its own and the lower folders on the include path, so an include of a
# higher layer does not build; each library layer is one archive, libsus_LAYER.a.
LIB_LAYERS := util core methods lab render prog
inc_util    := -Isrc/util
inc_core    := $(inc_util) -Isrc/core
inc_methods := $(inc_core) -Isrc/methods
inc_lab     := $(inc_methods) -Isrc/lab
inc_render  := $(inc_lab) -Isrc/render
inc_prog    := $(inc_render) -Isrc/prog
inc_tests   := $(inc_prog) -Itests/unit -Itests/ledger
CFLAGS_OF   = $(WARN) $(CFLAGS) $(SANFLAGS) $(inc_$(1)) $(PKG_CFLAGS) -MMD -MP

# The programs' main files (wasm_api.c: the browser's, built only for WebAssembly); the other
# files of src/prog (suslov's option table, parser and progress line, the animation's video) are
# the programs' own support, archived like a layer.
PROG_MAIN := src/prog/suslov.c src/prog/bench.c src/prog/animation.c $(wildcard src/prog/figure_*.c) \
             src/prog/wasm_api.c src/prog/timed.c
src_of  = $(filter-out $(PROG_MAIN),$(sort $(wildcard src/$(1)/*.c)))
obj_of  = $(patsubst src/%.c,$(BUILD)/obj/%.o,$(call src_of,$(1)))
lib_of  = $(BUILD)/libsus_$(1).a
# Link order: higher layers first (LIB_LAYERS reversed), so each archive resolves against the
# ones after it.
reverse = $(if $(1),$(call reverse,$(wordlist 2,$(words $(1)),$(1))) $(firstword $(1)))
LIBS_LINK := $(foreach l,$(call reverse,$(LIB_LAYERS)),$(call lib_of,$(l)))

FIG_SRC  := $(wildcard src/prog/figure_*.c)
FIGS     := $(FIG_SRC:src/prog/figure_%.c=%)
FIG_BIN  := $(FIGS:%=$(BUILD)/figure_%)
# The bench's figures, drawn from the recorded run (make bench-record, below)
BENCH_REC  := data/bench-recorded
BENCH_FIGS := figures/work_precision.pdf figures/work_precision.png \
              figures/work_precision_best.pdf figures/work_precision_best.png \
              figures/step_cost.pdf figures/step_cost.png
TESTS    := $(patsubst tests/unit/%.c,$(BUILD)/%,$(wildcard tests/unit/test_*.c))
RENDER_H := $(notdir $(wildcard src/render/*.h))
# (stdin from /dev/null: in a tree without src/render, grep gets no pattern and would read it)
TESTS_DRAW := $(patsubst tests/unit/%.c,$(BUILD)/%,$(shell grep -lF $(RENDER_H:%=-e '"%"') \
                  tests/unit/test_*.c </dev/null 2>/dev/null))
CLAIMS   := $(BUILD)/claims
LEDGER_INPROC := $(BUILD)/ledger-inproc/claims.out
TIMED    := $(BUILD)/timed

# Stamps that change only when their text does: the compile flags (a change of CFLAGS, WERROR or
# SAN recompiles everything) and each archive's member list (a deleted source leaves no stale
# object in its archive). A stamp whose file already holds its text has no rule and so is up to
# date; otherwise it gets one that rewrites it. Nothing is written while the Makefile is read,
# so `make -n` and `make -q` change nothing, and `make -q all` answers truthfully.
define STAMP_RULE
ifneq ($$(strip $$(file <$(1))),$$(strip $(2)))
$(1): FORCE
	@mkdir -p $$(@D); echo '$$(strip $(2))' >$$@
endif
endef
$(eval $(call STAMP_RULE,$(BUILD)/flags.stamp,$(CC) $(WARN) $(CFLAGS) $(SANFLAGS) $(LDFLAGS) | $(CXX)))
$(foreach l,$(LIB_LAYERS),$(eval $(call STAMP_RULE,$(BUILD)/libsus_$(l).list,$(call obj_of,$(l)))))

.PHONY: FORCE all deps deps-figures deps-paper deps-bench test ledger ledger-inproc check figures animation bench bench-record paper clean distclean
all: $(BUILD)/suslov $(BUILD)/man/suslov.1 $(BUILD)/bench $(BUILD)/animation $(FIG_BIN) $(TESTS) $(CLAIMS) \
     $(TIMED)

# What each goal needs (tools/deps.sh PROFILE): check = compiler, GSL, Cairo, OSMesa, fonts;
# figures adds ffmpeg; paper adds TeX. Objects wait only on the check profile, through a stamp
# (an always-run rule would make `make -q` always answer "not up to date").
deps: deps-paper deps-bench
deps-figures deps-paper:
	@sh tools/deps.sh $(@:deps-%=%)
DEPS_CHECK := $(BUILD)/deps-check.stamp
# A make value as one single-quoted shell word.
sq = '$(subst ','\'',$(1))'
# It runs again when the compiler changes (flags.stamp holds $(CC)): make CC=clang installs clang.
$(DEPS_CHECK): tools/deps.sh $(BUILD)/flags.stamp
	@CC=$(call sq,$(CC)) CXX=$(call sq,$(CXX)) sh tools/deps.sh check && mkdir -p $(@D) && touch $@

$(BUILD)/obj/%.o: src/%.c $(BUILD)/flags.stamp | $(DEPS_CHECK)
	@mkdir -p $(@D)
	$(call say,CC,$<)
	$(Q)$(CC) $(call CFLAGS_OF,$(firstword $(subst /, ,$*))) $(VERSION_DEF) -c $< -o $@

$(BUILD)/tobj/%.o: tests/%.c $(BUILD)/flags.stamp | $(DEPS_CHECK)
	@mkdir -p $(@D)
	$(call say,CC,$<)
	$(Q)$(CC) $(call CFLAGS_OF,tests) -c $< -o $@

define ARCHIVE_RULE
$(call lib_of,$(1)): $(call obj_of,$(1)) $(BUILD)/libsus_$(1).list
	@rm -f $$@
	$$(call say,AR,$$@)
	$$(Q)$$(AR) rcs $$@ $(call obj_of,$(1))
endef
$(foreach l,$(LIB_LAYERS),$(eval $(call ARCHIVE_RULE,$(l))))

# --version names the commit built from (git describe; "unknown" outside git, e.g. a tarball),
# through a stamp that changes only when the commit does, so only the object that holds it
# (suslov_version.o, which --version, --man and the output's header read) is rebuilt then.
# Only when this directory is the top of its own work tree: a source export unpacked inside
# another repository's work tree must not carry that repository's commit.
SUSLOV_VERSION := $(shell top=$$(git -C "$(CURDIR)" rev-parse --show-toplevel 2>/dev/null) && \
    [ "$$top" = "$$(cd "$(CURDIR)" && pwd -P)" ] && git -C "$(CURDIR)" describe --always --dirty 2>/dev/null \
    || echo unknown)
$(eval $(call STAMP_RULE,$(BUILD)/version.stamp,$(SUSLOV_VERSION)))
VERSION_OBJ := $(BUILD)/obj/prog/suslov_version.o
$(VERSION_OBJ): $(BUILD)/version.stamp
$(VERSION_OBJ): VERSION_DEF = -DSUSLOV_VERSION='"$(SUSLOV_VERSION)"'

$(BUILD)/suslov: $(BUILD)/obj/prog/suslov.o $(LIBS_LINK)
	$(call say,LD,$@)
	$(Q)$(CC) $(ALL_LDFLAGS) $^ $(LIBS_RUN) -o $@

# Runs a long step (the figure programs, the ledger, the tests, the bench): records its time under
# $(BUILD)/timings and, with --progress, shows its progress against the last run's time
# (src/prog/timed.c). Order-only where it wraps a figure: rebuilding it redraws nothing.
$(TIMED): $(BUILD)/obj/prog/timed.o $(LIBS_LINK)
	$(call say,LD,$@)
	$(Q)$(CC) $(ALL_LDFLAGS) $^ $(LIBS_RUN) -o $@

# A program that draws files depends on the objects it links, not on the whole archives: the
# linker's --trace given twice names the archive members it pulled, and $@.link.d makes the
# program depend on exactly those (a new reference can only come from a changed object already
# linked). The archives are order-only, so a change to an object the program does not link
# relinks nothing and redraws nothing. If the trace names no member (another linker), depend
# on the archives. Each member also gets an empty rule, so that a deleted source's object no longer
# stops the build (make then finds its recipe, if any, in the pattern rule).
DRAW_PROGS := $(BUILD)/animation $(BUILD)/bench $(FIG_BIN)
$(DRAW_PROGS): $(BUILD)/%: $(BUILD)/obj/prog/%.o | $(LIBS_LINK)
	$(call say,LD,$@)
	$(Q)$(CC) $(ALL_LDFLAGS) $< $(LIBS_LINK) $(LIBS_DRAW) -o $@ -Wl,--trace,--trace >$@.trace
	@$(LINK_D)
# $@.link.d from the linker's trace $@.trace (which it removes)
LINK_D = objs=$$(sed -n -e 's|^(.*libsus_\([a-z]*\)\.a)\(.*\.o\)$$|$(BUILD)/obj/\1/\2|p' \
	    -e 's|^.*libsus_\([a-z]*\)\.a(\(.*\.o\))$$|$(BUILD)/obj/\1/\2|p' $@.trace | sort -u | tr '\n' ' '); \
	    { echo "$@: $${objs:-$(LIBS_LINK)}"; for o in $$objs; do echo "$$o:"; done; } >$@.link.d; rm -f $@.trace

$(TESTS): $(BUILD)/test_%: $(BUILD)/tobj/unit/test_%.o $(LIBS_LINK)
	$(call say,LD,$@)
	$(Q)$(CC) $(ALL_LDFLAGS) $^ $(if $(filter $@,$(TESTS_DRAW)),$(LIBS_DRAW),$(LIBS_RUN)) -o $@

# The attitude-order test takes its expected orders from the ledger's table of the theory.
$(BUILD)/test_attitude_order: $(BUILD)/tobj/ledger/expected_orders.o

# The claims program is linked as a drawing program is: it depends on the archive members it links,
# so that a change to one it does not (the version stamp's object, at every commit) neither
# relinks it nor runs the ledger again. Until its $@.link.d exists, on the whole archives.
CLAIMS_OBJ := $(patsubst tests/%.c,$(BUILD)/tobj/%.o,$(wildcard tests/ledger/*.c))
$(CLAIMS): $(CLAIMS_OBJ) | $(LIBS_LINK)
	$(call say,LD,$@)
	$(Q)$(CC) $(ALL_LDFLAGS) $(CLAIMS_OBJ) $(LIBS_LINK) $(LIBS_RUN) -o $@ -Wl,--trace,--trace >$@.trace
	@$(LINK_D)
ifeq ($(wildcard $(CLAIMS).link.d),)
$(CLAIMS): $(LIBS_LINK)
endif

# A figure program writes its figure (PDF, PNG, caption) and its data together; it runs again
# only when the program (or anything it is linked from) changes. The figures' tools (ffmpeg) are
# checked through a stamp, as the check profile's are, so that `make -q figures` answers 0 when
# every figure is up to date (an always-run prerequisite would make it answer 1 for ever). The
# last line says what was written and where; not under -q, where a recipe would make `figures`
# out of date for ever. The two long ones come first, so that under make -j the short ones fill
# the cores beside them instead of leaving one of them to run alone at the end (figure_stability
# splits its own runs across the cores: figure_stability --jobs N, SUSLOV_JOBS).
figures: figures/stability.pdf animation $(filter-out figures/stability.pdf,$(FIGS:%=figures/%.pdf)) \
         $(BENCH_FIGS)
ifeq ($(findstring q,$(firstword -$(MAKEFLAGS))),)
	@echo "figures: $(words $(FIGS)) figures in figures/ (NAME.pdf, a NAME.png preview, the caption" \
	    "NAME.txt) with their data in data/NAME.csv; the bench's two from its recorded run" \
	    "(data/bench-recorded/); the animation in figures/attitude.mp4, figures/attitude/ and" \
	    "figures/attitude_filmstrip.png"
endif
DEPS_FIGURES := $(BUILD)/deps-figures.stamp
$(DEPS_FIGURES): tools/deps.sh
	@sh tools/deps.sh figures && mkdir -p $(@D) && touch $@

# The attitude animation: frames, video (when ffmpeg is installed), filmstrip, caption and the
# R_k it draws.
animation: figures/attitude_filmstrip.png

figures/attitude_filmstrip.png figures/attitude.txt data/attitude.csv &: $(BUILD)/animation data/animation.cfg \
    | $(DEPS_FIGURES) $(TIMED)
	@mkdir -p figures data
	$(call say,FIG,figures/attitude)
	$(Q)$(TIMED) $(BUILD)/timings/animation.txt $< data/animation.cfg figures data

# Every figure output is written atomically by its program (src/util/atomic_file.c), so an
# interrupted make must never delete one: a half-made file cannot exist.
.PRECIOUS: figures/%.pdf figures/%.png figures/%.txt data/%.csv figures/attitude_filmstrip.png \
           figures/attitude.txt data/attitude.csv
# A program that shows no progress of its own gets the wrapper's, against its last run's time.
OWN_PROGRESS := stability
figures/%.pdf figures/%.png figures/%.txt data/%.csv: $(BUILD)/figure_% | $(DEPS_FIGURES) $(TIMED)
	@mkdir -p figures data
	$(call say,FIG,figures/$*)
	$(Q)$(TIMED) $(if $(filter $*,$(OWN_PROGRESS)),,--progress figure_$*) $(BUILD)/timings/figure_$*.txt \
	    $< figures data

# make test: the unit tests, the CLI tests and the build checks, exactly $(TESTS) and the scripts
# named in tests/run.sh (a few seconds). make ledger: the claims ledger, run again only when the
# claims program, suslov or its one input changed (the recorded bench's settings, what_to_use.tsv,
# which it runs with suslov and checks at their levels); its table is kept in $(BUILD)/claims.out
# and printed whole (make check prints the lines whose check failed and the findings; V=1 the
# table). make check: both, and "N passed, N failed" over all of them on the last line.
# The suppressions path is quoted for LSan, so that a checkout path with a space works.
SAN_ENV = SUSLOV_SAN=$(filter 1,$(SAN)) \
    LSAN_OPTIONS="suppressions='$(CURDIR)/tests/build/lsan.supp':print_suppressions=0"
test: all
	@$(SAN_ENV) $(TIMED) $(BUILD)/timings/test.txt sh tests/run.sh $(BUILD) test $(TESTS)

ledger: $(BUILD)/claims.out
	@sh tests/run.sh $(BUILD) ledger

check: all $(BUILD)/claims.out
	@$(SAN_ENV) $(TIMED) $(BUILD)/timings/check.txt sh tests/run.sh $(BUILD) check $(TESTS)

# The ledger runs suslov on the recorded bench's settings (tests/ledger/claims_recommended.c): it
# runs again when an object suslov is linked from changes, but not for the version stamp's alone
# (a new commit), which changes only the first line of suslov's header.
LEDGER_SUSLOV := $(BUILD)/obj/prog/suslov.o \
                 $(filter-out $(VERSION_OBJ),$(foreach l,$(LIB_LAYERS),$(call obj_of,$(l))))

# The ledger writes claims.tsv and, beside it, the companion's numbers.tex, ledger.tex,
# summary.tex and sensitivity.tex (the table of Figure 2's statements over steps, bodies and
# starts), and the web edition's claims_tex.tsv (each line's quantity and test in that LaTeX),
# and prints its table (claims.out). A run that does not reach its summary line
# (a crash, a measurement that could not be made) leaves no output, so it runs again. ($@ of a
# grouped rule is whichever target asked for it: the tables' paths are spelled out.)
# The ledger runs each section in a process of its own, on every core (tests/ledger/ledger_jobs.h).
LEDGER_OUT := $(BUILD)/claims.tsv $(BUILD)/methods.tsv $(BUILD)/numbers.tex $(BUILD)/ledger.tex $(BUILD)/summary.tex \
              $(BUILD)/sensitivity.tex $(BUILD)/claims_tex.tsv
LEDGER_IN := $(CLAIMS) $(BENCH_REC)/what_to_use.tsv $(LEDGER_SUSLOV)
# ledger_keep OUT,ALSO,NAME: OUT.tmp becomes OUT when the claims program reached its summary line;
# else it is shown, removed with ALSO, and the recipe fails
ledger_keep = if grep -q '^claims: [0-9]* passed' $(1).tmp; then mv $(1).tmp $(1); \
    else cat $(1).tmp; rm -f $(1).tmp $(2); echo "$(3): the claims program stopped early"; exit 1; fi
$(BUILD)/claims.out $(LEDGER_OUT) &: $(LEDGER_IN) | $(TIMED) $(BUILD)/suslov
	$(call say,LEDGER,$(BUILD)/claims.tsv)
	$(Q)$(SAN_ENV) $(TIMED) --progress ledger --output $(BUILD)/claims.out.tmp \
	    $(BUILD)/timings/ledger.txt $(CLAIMS) $(BUILD)/claims.tsv; \
	$(call ledger_keep,$(BUILD)/claims.out,$(LEDGER_OUT),ledger)

# The ledger is the same byte for byte as a run of one section after the other in one process
# (claims --in-process, into $(BUILD)/ledger-inproc), which a section leaning on another's state
# would fail (tests/build/ledger_inproc.sh). CI checks it; make check does not, as it would double
# the ledger's time.
ledger-inproc: $(LEDGER_INPROC) $(BUILD)/claims.out
	@sh tests/build/ledger_inproc.sh $(BUILD) $(notdir $(BUILD)/claims.out $(LEDGER_OUT))
$(LEDGER_INPROC): $(LEDGER_IN) | $(TIMED) $(BUILD)/suslov
	$(call say,LEDGER,$(BUILD)/ledger-inproc/ in one process)
	$(Q)mkdir -p $(@D); $(SAN_ENV) $(TIMED) --output $@.tmp $(BUILD)/timings/ledger-inproc.txt \
	    $(CLAIMS) --in-process $(@D)/claims.tsv; \
	$(call ledger_keep,$@,,ledger --in-process)

# The fuzzer (tests/cli/fuzz*.c): random and hostile argument vectors against $(BUILD)/suslov for T
# seconds with the fixed seed SEED (printed, for replay), checking every promise of the
# interface; last line "fuzz: N passed, N failed". CI runs it under SAN=1.
T    ?= 60
SEED ?= 20261122
.PHONY: fuzz
fuzz: $(BUILD)/suslov $(BUILD)/fuzz
	@$(SAN_ENV) $(BUILD)/fuzz $(BUILD)/suslov $(T) $(SEED)

$(BUILD)/fuzz: $(patsubst tests/%.c,$(BUILD)/tobj/%.o,$(wildcard tests/cli/fuzz*.c))
	$(call say,LD,$@)
	$(Q)$(CC) $(ALL_LDFLAGS) $^ -o $@

# Speed and accuracy: the PASS/MISS/UNDECIDED lines of the speed targets (never a failing test). make bench
# writes a fresh run, whole or not at all, into data/bench-run/ and its figures into
# $(BUILD)/bench-run/; make bench-record writes the run the companion and the docs quote into
# data/bench-recorded/ (committed: a deliberate step, the only one that writes there; BENCH_NOTE
# says what else ran on the machine) and draws the committed previews from it. Both time the
# Boost.Odeint peers too: bench.c again with SUSLOV_WITH_ODEINT, linked with
# src/prog/bench_odeint.cpp (g++ and the header-only Boost from `tools/deps.sh bench`, which make
# check never needs).
BENCH_NOTE ?=
bench: all $(BUILD)/bench_boost
	@$(TIMED) $(BUILD)/timings/bench.txt sh tools/bench.sh $(BUILD) "$(CFLAGS)" data/bench-run \
	    $(BUILD)/bench-run
bench-record: all $(BUILD)/bench_boost
	@sh tools/bench.sh $(BUILD) "$(CFLAGS)" $(BENCH_REC) $(BUILD)/bench-recorded $(call sq,$(BENCH_NOTE))
	@$(MAKE) --no-print-directory $(BENCH_FIGS)

# The bench's figures of the recorded run (the committed previews, and the PDF the software note
# prints): drawn from its data alone, in a second, so they are the same bytes every time.
.PRECIOUS: $(BENCH_FIGS)
$(BENCH_FIGS) &: $(BUILD)/bench $(BENCH_REC)/bench.csv
	@mkdir -p figures
	$(call say,FIG,figures/work_precision figures/work_precision_best figures/step_cost)
	$(Q)$(BUILD)/bench --plot figures $(BENCH_REC)

CXXWARN := -std=c++17 -Wall -Wextra -Wshadow $(filter -Werror,$(WARN))
deps-bench:
	@sh tools/deps.sh bench
$(BUILD)/obj/prog/bench_odeint.o: src/prog/bench_odeint.cpp $(BUILD)/flags.stamp | deps-bench
	@mkdir -p $(@D)
	$(call say,CXX,$<)
	$(Q)$(CXX) $(CXXWARN) $(CFLAGS) $(SANFLAGS) $(inc_prog) -MMD -MP -c $< -o $@
$(BUILD)/obj/prog/bench_boost.o: src/prog/bench.c $(BUILD)/flags.stamp | $(DEPS_CHECK)
	@mkdir -p $(@D)
	$(call say,CC,$< (with Boost.Odeint))
	$(Q)$(CC) $(call CFLAGS_OF,prog) -DSUSLOV_WITH_ODEINT -c $< -o $@
$(BUILD)/bench_boost: $(BUILD)/obj/prog/bench_boost.o $(BUILD)/obj/prog/bench_odeint.o $(LIBS_LINK)
	$(call say,LD,$@)
	$(Q)$(CXX) $(ALL_LDFLAGS) $^ $(LIBS_DRAW) -o $@

# The companion text: every number from the claims ledger (build/numbers.tex) and the recorded
# bench run (data/bench-recorded/bench.tex and machine.tex), figures from the figure programs and
# from the recorded run's data, listings and equation map from src/.
PAPER_IN := paper/companion.tex paper/methods.tex paper/preamble.tex paper/bibliography.tex $(wildcard paper/*.tsv) \
            $(BUILD)/claims.tsv paper/equations.txt $(BUILD)/numbers.tex $(BUILD)/ledger.tex \
            $(BUILD)/summary.tex $(BUILD)/sensitivity.tex $(BENCH_REC)/bench.tex $(BENCH_REC)/machine.tex \
            $(BENCH_REC)/bench.txt tools/bench_summary.sh tools/bench_misses.awk tools/latex.sh \
            tools/latex_esc.awk \
            $(FIGS:%=figures/%.pdf) figures/work_precision.pdf figures/work_precision_best.pdf \
            figures/attitude_filmstrip.png \
            $(wildcard src/*/*.c src/*/*.h) tools/paper.sh tools/snippet.sh tools/eqmap.sh \
            tools/paper_numbers.sh tools/paper_refs.sh tools/repro.sh tools/figsplit.sh \
            tools/paper_coverage.sh tools/paper_tables.sh tools/paper_layout.sh \
            tools/paper_tolerances.sh tools/paper_links.sh tools/paper_labels.py CITATION.cff .zenodo.json
paper: paper/companion.pdf paper/methods.pdf

# The companion (main text) and the software note (methods, benchmark, whole ledger, source),
# committed, with paper/ledger.sha256 (the ledger's outputs they print); only this rule writes
# them. PAPER_BASE=https://host/owner/repo/blob/COMMIT/ makes the code links absolute under one
# address (default: relative to paper/, resolved in the clone); a change of it rebuilds the PDFs.
PAPER_BASE ?=
$(eval $(call STAMP_RULE,$(BUILD)/paper_base.stamp,base=$(PAPER_BASE)))
paper/companion.pdf paper/methods.pdf paper/ledger.sha256 &: $(PAPER_IN) $(BUILD)/paper_base.stamp \
    | deps-paper
	$(call say,PAPER,paper/companion.pdf paper/methods.pdf)
	$(Q)PAPER_BASE='$(PAPER_BASE)' PAPER_TEX='$(PAPER_TEX)' sh tools/paper.sh $(BUILD)

# The web edition (tools/web/): a static site, the findings first, one page per statement of the
# paper, the ledger, the equations, the figures and one side-by-side page per source file, rebuilt
# when any of them changes. Its tools (Debian's python3-markdown, pygments, universal-ctags,
# chromium; KaTeX and playwright-core from npm) come from make web-deps, which make check never
# needs; their installers write to $(BUILD)/web-deps.log. /usr/bin/python3 is Debian's, the one
# with python3-markdown. The paper's LaTeX source (PAPER_TEX) gives the statements their quotes;
# without it the pages carry none, the numbers come from paper/labels.tsv, and make web says so in
# its one line. The figure programs' captions and data (seconds to draw) are prerequisites, so
# that a fresh clone's figures page is complete; make bench and make animation (minutes) are not:
# their figures show the committed PNG until they have run. A listing of the figure files' names
# and times is a prerequisite too, with the names in src/ and tests/ so that a removed file also
# rebuilds the site ($(WEB)/inputs.list, rewritten only when it changes). Quiet: one line per
# step; V=1 shows the commands.
WEB_Q     := $(if $(filter 1,$(V)),,@)
WEB       := $(BUILD)/web
WEB_PY    := /usr/bin/python3
PAPER_TEX ?= ../shared/seeds/000_7d469b10bebd47d3.txt
WEB_IN    := $(wildcard src/*/*.c src/*/*.h tests/*/*.c tests/*/*.h tests/*/*.sh tests/*.sh) paper/equations.txt \
             $(wildcard paper/*.tsv) $(BUILD)/claims.tsv $(BUILD)/methods.tsv $(WEB)/inputs.list \
             $(wildcard tools/web/*.py tools/web/*.tex tools/web/*.tsv tools/web/*.css) \
             $(wildcard tools/web/*.js tools/web/js/*.js) tools/web/package-lock.json
.PHONY: web web-deps check-web FORCE
web: $(WEB)/index.html

# The integrators for the browser (the live pages): the library's C sources that reach no GSL,
# Cairo, libpng, OpenGL or signal header (tools/web/wasm_sources.sh), compiled to WebAssembly with
# clang --target=wasm32-wasi and Debian's wasi-libc (make web-deps installs them), linked through
# an archive so that the module holds only what src/wasm_api.c reaches. A method left out (its
# source needs GSL) fails the link by name.
WASM      := $(BUILD)/wasm/suslov.wasm
WASM_CC   ?= clang
WASM_AR   ?= llvm-ar
# (a tree without tools/web, as the build checks' scratch trees, has no browser part to build)
# Listed only for a goal that reaches the WebAssembly build: the script greps every source, a
# second or more, too long for every make (make check runs make many times over).
WASM_GOALS := wasm web check-web web-shots $(WASM) $(WEB)/index.html
WASM_SRC  := $(if $(filter $(WASM_GOALS),$(MAKECMDGOALS)),$(if $(wildcard \
                 tools/web/wasm_sources.sh),$(shell sh tools/web/wasm_sources.sh)))
WASM_OBJ  := $(WASM_SRC:src/%.c=$(BUILD)/wasm/%.o)
WASM_EXPORTS := input inertia_column rows nrows message limit method_count method_name method_about \
                method_recon recon_count recon_name run sweeps exact_omega fit_input fit
.PHONY: wasm
wasm: $(WASM)

# WASM_CC is clang whatever CC is: its unroll notes are not warnings here either (WARN, above).
$(BUILD)/wasm/%.o: src/%.c | web-deps
	@mkdir -p $(@D)
	$(WEB_Q)$(WASM_CC) --target=wasm32-wasi $(WARN) -Wno-pass-failed -O2 $(inc_prog) -MMD -MP -c $< -o $@

$(WASM): $(WASM_OBJ)
	@echo "WASM  $@ ($(words $(WASM_OBJ)) sources)"
	@rm -f $(@D)/libsuslov.a
	$(WEB_Q)$(WASM_AR) rcs $(@D)/libsuslov.a $(filter-out %/wasm_api.o,$^)
	$(WEB_Q)$(WASM_CC) --target=wasm32-wasi -O2 -nostartfiles -Wl,--no-entry \
	    $(WASM_EXPORTS:%=-Wl,--export=wasm_%) $(filter %/wasm_api.o,$^) $(@D)/libsuslov.a -lm -o $@.tmp
	@mv $@.tmp $@
-include $(WASM_OBJ:.o=.d)

$(WEB)/index.html: $(WEB_IN) $(BUILD)/claims_tex.tsv $(WASM) $(FIGS:%=figures/%.txt) | web-deps
	$(WEB_Q)$(WEB_PY) tools/web/build.py --out $(WEB) --claims $(BUILD)/claims.tsv --paper $(PAPER_TEX) \
	    --wasm $(WASM)

$(WEB)/inputs.list: FORCE
	@mkdir -p $(@D)
	@{ ls -l --time-style=+%s figures/*.png figures/*.txt data/*.csv; \
	   find src tests paper -name '*.[ch]' -o -name '*.tsv'; } >$@.tmp 2>/dev/null || true
	@if cmp -s $@.tmp $@; then rm -f $@.tmp; else mv $@.tmp $@; fi

web-deps:
	@sh tools/web/deps.sh $(BUILD)/web-deps.log

# Every page in headless chromium: links, math, no network, no sideways scroll at 390 and 1400 px,
# the home page's findings and figure, each statement's quote, the ledger's cards at both widths,
# its search and code links, the live pages' numbers against build/suslov's CSV, their labels and
# ticks, the (taudyn) page and its screenshot ($(WEB)/shots/taudyn.png).
# Last line "check-web: N passed, N failed".
check-web: web $(BUILD)/suslov
	$(WEB_Q)node tools/web/check_web.js $(WEB) paper/equations.txt $(BUILD)/claims.tsv $(BUILD)/suslov

# Screenshots of the pages a reader meets first, at 390 and 1400 px, for a person to look at:
# $(WEB)/shots/PAGE-WIDTH.png (tools/web/shots.js).
WEB_SHOTS ?= index.html statements.html stmt-TeoL.html stmt-Fig2.html ledger.html ledger.html\#g-TeoL \
             figures.html equations.html live-fig2.html live-attitude.html
.PHONY: web-shots
web-shots: web
	@node tools/web/shots.js $(WEB) $(WEB)/shots $(WEB_SHOTS)

# The mutation check: each one-line mutant of tests/build/mutants is applied to a scratch copy of the
# tree, which is rebuilt and tested; every mutant must be killed (tools/mutants.sh). CI runs
# the fixed subset MUTANTS_STRIDE=k: mutants 1, 1+k, 1+2k, ...
.PHONY: mutants
mutants: | $(DEPS_CHECK)
	@sh tools/mutants.sh tests/build/mutants $(MUTANTS_STRIDE)

# The generated operator-mutation campaign (tools/mutants_ops.py): every floating literal scaled,
# + <-> -, * <-> /, array index +-1, comparison negated, over the library files in priority order;
# last line "mutants-ops: generated N, killed K, equivalent E, survived S, did-not-build B, score X".
# MUTANTS_OPS_SAMPLE=N runs a seeded sample of N (seed MUTANTS_OPS_SEED; CI), MUTANTS_OPS_FILES
# a subset of the files. The result (one line a mutant, with its commit) and the log are generated
# files under $(BUILD); the last complete campaign is recorded in data/mutants_ops_log.tsv.gz and
# tests/build/mutants_ops_summary.txt (tools/mutants_ops.py --record writes them, by hand).
MUTANTS_OPS_SAMPLE ?= 0
MUTANTS_OPS_SEED   ?= 20261123
MUTANTS_OPS_OUT    ?= $(if $(filter 0,$(MUTANTS_OPS_SAMPLE)),$(BUILD)/mutants_ops_result.txt,$(BUILD)/mutants_ops_sample.txt)
# Each mutant's verdict is appended to the log as it finishes; MUTANTS_OPS_RESUME=1 skips the
# mutants the log already holds (a campaign cut short goes on where it stopped) but runs its
# survivors again, and a full campaign with no log yet starts from the recorded one.
MUTANTS_OPS_LOG    ?= $(if $(filter 0,$(MUTANTS_OPS_SAMPLE)),$(BUILD)/mutants_ops_log.tsv,$(BUILD)/mutants_ops_sample.log)
MUTANTS_OPS_RECORD := data/mutants_ops_log.tsv.gz
.PHONY: mutants-ops deps-mutants
deps-mutants:
	@sh tools/deps.sh mutants
mutants-ops: | deps-mutants
	@mkdir -p $(BUILD)/mutants_ops
	@python3 tools/mutants_ops.py --sample $(MUTANTS_OPS_SAMPLE) --seed $(MUTANTS_OPS_SEED) \
	    --out $(MUTANTS_OPS_OUT) --log $(MUTANTS_OPS_LOG) $(if $(filter 1,$(MUTANTS_OPS_RESUME)),--resume) \
	    $(if $(filter 0,$(MUTANTS_OPS_SAMPLE)),--from-log $(MUTANTS_OPS_RECORD)) \
	    $(if $(MUTANTS_OPS_FILES),--files $(MUTANTS_OPS_FILES))

# The manual page, written by suslov itself from the option table that --help prints.
$(BUILD)/man/suslov.1: $(BUILD)/suslov
	@mkdir -p $(@D)
	$(call say,GEN,$@)
	$(Q)$< --man >$@.tmp && mv $@.tmp $@

# make install PREFIX=DIR (and DESTDIR= for staging): the command, its manual page, and the
# library for C and C++ programs: libsuslov.a (the core and methods layers, which need only libm)
# in lib/, the public header suslov.h and the headers it includes (no other) in include/suslov/,
# and suslov.pc, so that a program includes <suslov/suslov.h> and builds with
# `cc prog.c $$(pkg-config --cflags --libs suslov)` (eval it in a shell: a space in PREFIX is
# escaped). make uninstall removes exactly these files (and include/suslov). PREFIX must be
# absolute, of letters, digits, space and /._-+,:@=~% (what pkg-config's output can carry).
PREFIX ?= /usr/local
INSTALL_LAYERS := core methods
PUBLIC_H = $(sort $(filter %.h,$(shell $(CC) -MM $(inc_methods) src/methods/suslov.h)))
INSTALL_OBJ := $(foreach l,$(INSTALL_LAYERS),$(call obj_of,$(l)))
# One archive for the user, libsuslov.a: the members of those layers' archives.
$(BUILD)/libsuslov.a: $(INSTALL_OBJ) $(foreach l,$(INSTALL_LAYERS),$(BUILD)/libsus_$(l).list)
	@rm -f $@
	$(call say,AR,$@)
	$(Q)$(AR) rcs $@ $(INSTALL_OBJ)
ifneq ($(filter install uninstall,$(MAKECMDGOALS)),)
ifneq ($(shell case $(call sq,$(PREFIX)) in (/*) echo absolute;; esac),absolute)
$(error PREFIX='$(PREFIX)' is not an absolute directory)
endif
ifneq ($(shell printf '%s' $(call sq,$(PREFIX)) | tr -d 'A-Za-z0-9/._+,:@=~% -'),)
$(error PREFIX='$(PREFIX)' holds a character pkg-config cannot carry: use letters, digits, space, /._-+,:@=~%)
endif
endif
.PHONY: install uninstall
install: $(BUILD)/suslov $(BUILD)/libsuslov.a $(BUILD)/man/suslov.1
	@d=$(call sq,$(DESTDIR)$(PREFIX)); set -e; \
	    install -d "$$d/bin" "$$d/lib/pkgconfig" "$$d/share/man/man1"; \
	    rm -rf "$$d/include/suslov"; install -d "$$d/include/suslov"; \
	    install -m 755 $(BUILD)/suslov "$$d/bin/suslov"; \
	    install -m 644 $(BUILD)/libsuslov.a "$$d/lib/libsuslov.a"; \
	    install -m 644 $(PUBLIC_H) "$$d/include/suslov/"; \
	    install -m 644 $(BUILD)/man/suslov.1 "$$d/share/man/man1/suslov.1"; \
	    p=$$(printf '%s' $(call sq,$(PREFIX)) | sed 's/ /\\ /g'); \
	    { echo "prefix=$$p"; echo 'libdir=$${prefix}/lib'; echo 'includedir=$${prefix}/include'; \
	      echo; echo 'Name: suslov'; \
	      echo 'Description: integrators of the Suslov problem (Jimenez & Scheurle 2018)'; \
	      echo 'Version: $(SUSLOV_VERSION)'; echo 'Cflags: -I$${includedir}'; \
	      echo 'Libs: -L$${libdir} -lsuslov -lm'; } >"$$d/lib/pkgconfig/suslov.pc"; \
	    echo "installed into $$d"

uninstall:
	@d=$(call sq,$(DESTDIR)$(PREFIX)); \
	    rm -f "$$d/bin/suslov" "$$d/lib/libsuslov.a" "$$d/lib/pkgconfig/suslov.pc" \
	        "$$d/share/man/man1/suslov.1" && rm -rf "$$d/include/suslov" && echo "uninstalled from $$d"

clean:
	$(call say,CLEAN,$(BUILD))
	$(Q)rm -rf $(BUILD)

# Everything `make figures`, `make bench` and `make paper` write but what is committed: the PNG
# previews the README shows, data/animation.cfg, the recorded bench run, and the PDFs with their
# paper/ledger.sha256 stay (in a git checkout, a PNG that git does not track goes too).
distclean: clean
	rm -rf figures/*.pdf figures/*.txt figures/*.tmp.* figures/.tmp.* figures/attitude figures/attitude.mp4 \
	    data/*.csv data/*.tex data/*.tmp.* data/.tmp.* data/bench-run paper/*.tmp
	@if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then \
	    for f in figures/*.png; do \
	        [ ! -e "$$f" ] || git ls-files --error-unmatch "$$f" >/dev/null 2>&1 || { echo "rm -f $$f"; rm -f "$$f"; }; \
	    done; \
	fi

# Only the dependency files of sources that still exist: a deleted source's old .d would name it
# as a prerequisite that no rule can make.
-include $(wildcard $(patsubst src/%,$(BUILD)/obj/%.d,$(basename $(wildcard src/*/*.c src/*/*.cpp))) \
    $(patsubst tests/%.c,$(BUILD)/tobj/%.d,$(wildcard tests/*/*.c)) $(BUILD)/obj/prog/bench_boost.d $(BUILD)/*.link.d)
