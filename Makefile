# spcontact build.  `make run` runs the default case, `make check` the test suite.
# PETSc: Debian's petsc-dev through pkg-config, or your own with PETSC_DIR (and PETSC_ARCH).
.DEFAULT_GOAL := all
SHELL := /bin/bash

ifneq ($(PETSC_DIR),)
  export PKG_CONFIG_PATH := $(PETSC_DIR)/$(PETSC_ARCH)/lib/pkgconfig:$(PETSC_DIR)/lib/pkgconfig:$(PKG_CONFIG_PATH)
endif
PETSC_CFLAGS = $(shell pkg-config --cflags PETSc 2>/dev/null)
PETSC_LIBS   = $(shell pkg-config --libs PETSc 2>/dev/null)
HDF5_CFLAGS  = $(shell pkg-config --cflags hdf5-openmpi 2>/dev/null)
HDF5_LIBS    = $(shell pkg-config --libs hdf5-openmpi 2>/dev/null)

CC       = mpicc
CFLAGS  ?= -O2 -g
CFLAGS  += -std=c99 -Wall -Wextra -Wno-unused-parameter -MMD -MP
CPPFLAGS = -Iinclude $(PETSC_CFLAGS) $(HDF5_CFLAGS)
LDLIBS   = $(PETSC_LIBS) $(HDF5_LIBS) -lmetis -lyaml -lm

SRC  := $(wildcard src/*.c src/materials/*.c src/methods/*.c)
OBJ  := $(SRC:%.c=build/%.o)
GEO  := $(wildcard input/*.geo)
MSH  := $(GEO:input/%.geo=build/mesh/%.msh)
# unit drivers: tests/unit/NAME.c -> bin/NAME (header-only kernels and the code's functions, the
# same flags as the code; linked with every object but main's)
UNIT := $(patsubst tests/unit/%.c,bin/%,$(wildcard tests/unit/*.c))
LIBOBJ := $(filter-out build/src/main.o,$(OBJ))

.PHONY: all deps run check clean meshes petsc-found unit FORCE
all: deps
	@$(MAKE) --no-print-directory bin/spcontact $(UNIT) meshes

deps:
	@bash scripts/setup-deps.sh

petsc-found:
	@pkg-config --exists PETSc || { echo "error: PETSc not found by pkg-config (module PETSc). Install Debian's petsc-dev (make deps) or set PETSC_DIR/PETSC_ARCH to your PETSc build." >&2; exit 1; }

# The code's version (git describe; "unknown" outside a git checkout) for -version and the summary:
# build/version.h is rewritten only when it changes, so only main.o and app.o follow it
VERSION := $(shell git describe --always --dirty 2>/dev/null || echo unknown)
build/version.h: FORCE
	@mkdir -p build; v='#define SP_VERSION "$(VERSION)"'; [ "$$(cat $@ 2>/dev/null)" = "$$v" ] || echo "$$v" >$@
build/src/main.o build/src/app.o: build/version.h
build/src/main.o build/src/app.o: CPPFLAGS += -Ibuild
FORCE:

bin/spcontact: $(OBJ) | petsc-found
	@mkdir -p bin
	$(CC) -o $@ $(OBJ) $(LDLIBS)

build/%.o: %.c | petsc-found
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(CFLAGS) -c $< -o $@

# `all` builds the unit drivers; `unit` names them (after `all`, so deps run first)
unit: all
$(UNIT): bin/%: build/unit/%.o $(LIBOBJ) | petsc-found
	@mkdir -p bin
	$(CC) -o $@ $< $(LIBOBJ) $(LDLIBS)
build/unit/%.o: tests/unit/%.c | petsc-found
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(CFLAGS) -c $< -o $@

meshes: $(MSH)
build/mesh/%.msh: input/%.geo
	@mkdir -p build/mesh
	@dim=$$(grep -q "Physical Volume" $< && echo 3 || echo 2); \
	  echo "gmsh -$$dim $< -> $@"; gmsh -v 2 -$$dim -format msh22 -o $@ $< >/dev/null

# The main job: the default benchmark case (see README).
run: all
	@source scripts/env.sh && bash scripts/run-default.sh

check: all unit
	@bash tests/run.sh

clean:
	rm -rf build bin

-include $(OBJ:.o=.d) $(UNIT:bin/%=build/unit/%.d)
