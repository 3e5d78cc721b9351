# Reproducible companion to Jimenez & Scheurle, "On some aspects of the discretization of the
# Suslov problem". `make check` runs the tests and the claims ledger; see README.md.
#
#   make            build build/suslov and the test programs
#   make check      unit tests + claims ledger (build/claims.tsv); last line "N passed, N failed"
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
# Deferred (=) so that pkg-config runs after `deps` has installed GSL.
GSL_CFLAGS = $(shell pkg-config --cflags gsl)
GSL_LIBS   = $(shell pkg-config --libs gsl)
ALL_CFLAGS = $(WARN) $(CFLAGS) -Isrc $(GSL_CFLAGS) -MMD -MP

LIB_SRC  := $(filter-out src/suslov.c,$(wildcard src/*.c))
LIB_OBJ  := $(LIB_SRC:src/%.c=$(BUILD)/obj/%.o)
LIB      := $(BUILD)/libsuslov.a
TESTS    := $(patsubst tests/%.c,$(BUILD)/%,$(wildcard tests/test_*.c))
CLAIMS   := $(BUILD)/claims

.PHONY: all deps check clean
.SECONDARY:
all: $(BUILD)/suslov $(TESTS) $(CLAIMS)

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
	$(CC) $(LDFLAGS) $^ $(GSL_LIBS) -lm -o $@

$(BUILD)/test_%: $(BUILD)/tobj/test_%.o $(LIB)
	$(CC) $(LDFLAGS) $^ $(GSL_LIBS) -lm -o $@

$(CLAIMS): $(BUILD)/tobj/claims.o $(BUILD)/tobj/ledger.o $(LIB)
	$(CC) $(LDFLAGS) $^ $(GSL_LIBS) -lm -o $@

check: all
	@SUSLOV_SAN=$(filter 1,$(SAN)) sh tests/run.sh $(BUILD)

clean:
	rm -rf build

-include $(wildcard $(BUILD)/obj/*.d $(BUILD)/tobj/*.d)
