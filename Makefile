# Reproducible companion to Jimenez & Scheurle, "On some aspects of the discretization of the
# Suslov problem". `make check` runs the tests and the claims ledger; see README.md.
#
#   make            build build/suslov, the figure programs and the test programs
#   make check      unit tests + claims ledger (build/claims.tsv); last line "N passed, N failed"
#   make figures    every figure: figures/NAME.{pdf,png,txt} and data/NAME.csv
#   make bench      work-precision and per-step cost against GSL (data/bench.csv)
#   make paper      the companion text, paper/companion.pdf
#   make deps       install missing Debian packages
#   WERROR=1        treat warnings as errors (CI)
#   SAN=1           build into build/san with -fsanitize=address,undefined

CC      ?= cc
BUILD   ?= build
CFLAGS  ?= -O2 -g
WARN    := -std=c17 -Wall -Wextra -Wshadow -Wstrict-prototypes
ifeq ($(WERROR),1)
WARN    += -Werror
endif
ifeq ($(SAN),1)
BUILD   := build/san
CFLAGS  += -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
LDFLAGS += -fsanitize=address,undefined
endif
# Deferred (=) so that pkg-config runs after `deps` has installed the packages.
PKGS       = gsl cairo osmesa
PKG_CFLAGS = $(shell pkg-config --cflags $(PKGS))
PKG_LIBS   = $(shell pkg-config --libs $(PKGS))
ALL_CFLAGS = $(WARN) $(CFLAGS) -Isrc $(PKG_CFLAGS) -MMD -MP

FIG_SRC  := $(wildcard src/figure_*.c)
FIGS     := $(FIG_SRC:src/figure_%.c=%)
FIG_BIN  := $(FIGS:%=$(BUILD)/figure_%)
LIB_SRC  := $(filter-out src/suslov.c src/bench.c src/animation.c $(FIG_SRC),$(wildcard src/*.c))
LIB_OBJ  := $(LIB_SRC:src/%.c=$(BUILD)/obj/%.o)
LIB      := $(BUILD)/libsuslov.a
TESTS    := $(patsubst tests/%.c,$(BUILD)/%,$(wildcard tests/test_*.c))
CLAIMS   := $(BUILD)/claims

.PHONY: all deps check figures animation bench paper clean
.SECONDARY:
all: $(BUILD)/suslov $(BUILD)/bench $(BUILD)/animation $(FIG_BIN) $(TESTS) $(CLAIMS)

deps:
	@sh tools/deps.sh

$(BUILD)/obj/%.o: src/%.c | deps
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -c $< -o $@

$(BUILD)/tobj/%.o: tests/%.c | deps
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -Itests -c $< -o $@

$(LIB): $(LIB_OBJ)
	@rm -f $@
	$(AR) rcs $@ $^

$(BUILD)/suslov: $(BUILD)/obj/suslov.o $(LIB)
	$(CC) $(LDFLAGS) $^ $(PKG_LIBS) -lm -o $@

$(BUILD)/animation: $(BUILD)/obj/animation.o $(LIB)
	$(CC) $(LDFLAGS) $^ $(PKG_LIBS) -lm -o $@

$(BUILD)/bench: $(BUILD)/obj/bench.o $(LIB)
	$(CC) $(LDFLAGS) $^ $(PKG_LIBS) -lm -o $@

$(BUILD)/figure_%: $(BUILD)/obj/figure_%.o $(LIB)
	$(CC) $(LDFLAGS) $^ $(PKG_LIBS) -lm -o $@

$(BUILD)/test_%: $(BUILD)/tobj/test_%.o $(LIB)
	$(CC) $(LDFLAGS) $^ $(PKG_LIBS) -lm -o $@

CLAIMS_OBJ := $(patsubst tests/%.c,$(BUILD)/tobj/%.o,$(wildcard tests/claims*.c) tests/ledger.c)
$(CLAIMS): $(CLAIMS_OBJ) $(LIB)
	$(CC) $(LDFLAGS) $^ $(PKG_LIBS) -lm -o $@

# A figure program writes its figure (PDF, PNG, caption) and its data together; it runs again
# only when the program (or anything it is linked from) changes.
figures: $(FIGS:%=figures/%.pdf) animation

# The attitude animation: frames, video (when ffmpeg is installed), filmstrip, caption and the
# R_k it draws.
animation: figures/attitude_filmstrip.png

figures/attitude_filmstrip.png figures/attitude.txt data/attitude.csv &: $(BUILD)/animation data/animation.cfg
	@mkdir -p figures data
	$< data/animation.cfg figures data

figures/%.pdf figures/%.png figures/%.txt data/%.csv: $(BUILD)/figure_%
	@mkdir -p figures data
	$< figures data

check: all
	@SUSLOV_SAN=$(filter 1,$(SAN)) LSAN_OPTIONS=suppressions=$(CURDIR)/tests/lsan.supp:print_suppressions=0 \
	    sh tests/run.sh $(BUILD)

# Speed and accuracy: data/bench.csv, figures/work_precision and figures/step_cost, and the
# PASS/MISS lines of the speed targets (never a failing test).
bench: all
	@mkdir -p figures data
	@sh tools/bench.sh $(BUILD) "$(CFLAGS)"

# The companion text: every number from the claims ledger (build/numbers.tex) and the benchmark
# (data/bench.tex), figures from the figure programs, listings and equation map from src/.
$(BUILD)/claims.tsv $(BUILD)/numbers.tex $(BUILD)/ledger.tex &: $(CLAIMS)
	$(CLAIMS) $(BUILD)/claims.tsv >/dev/null

data/bench.tex data/bench.csv figures/work_precision.pdf figures/step_cost.pdf &: $(BUILD)/bench
	@mkdir -p figures data
	$< figures data >/dev/null

PAPER_IN := paper/companion.tex paper/equations.txt $(BUILD)/numbers.tex $(BUILD)/ledger.tex data/bench.tex \
            $(FIGS:%=figures/%.pdf) figures/work_precision.pdf figures/attitude_filmstrip.png \
            $(wildcard src/*.c src/*.h) tools/paper.sh tools/snippet.sh tools/eqmap.sh
paper: paper/companion.pdf

paper/companion.pdf: $(PAPER_IN) | deps
	@sh tools/paper.sh $(BUILD)

clean:
	rm -rf build

-include $(wildcard $(BUILD)/obj/*.d $(BUILD)/tobj/*.d)
