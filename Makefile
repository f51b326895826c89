# Makefile - the entry point for a newcomer on a fresh Debian 12 machine.
#
#   make demo    installs what is missing (apt-get, as root), bootstraps,
#                configures, builds and renders scenes/default.pov through
#                mpirun into demo.png
#   make check   the same set-up, then every test: a normal build and an
#                AddressSanitizer + UndefinedBehaviorSanitizer build
#
# The autotools build itself lives in configure.ac and Makefile.am and runs
# out of tree in build/ (and build-asan/), so this file is never replaced.

BUILD      ?= build
ASAN_BUILD ?= build-asan
JOBS       ?= $(shell nproc 2>/dev/null || echo 2)
NP         ?= 2
CONFIGURE_FLAGS ?=
ifeq ($(CI),true)
CONFIGURE_FLAGS += --enable-werror
endif

# OpenMPI refuses to run as root without these, and more ranks than cores
# needs oversubscription: set here so nobody has to know.
export OMPI_ALLOW_RUN_AS_ROOT = 1
export OMPI_ALLOW_RUN_AS_ROOT_CONFIRM = 1
export OMPI_MCA_rmaps_base_oversubscribe = 1
MPIRUN ?= mpirun --oversubscribe --bind-to none

DEB_PACKAGES = build-essential autoconf automake libtool pkg-config flex \
	bison libpng-dev libjpeg-dev libopenmpi-dev openmpi-bin libcmocka-dev \
	povray-includes

.PHONY: all deps bootstrap build demo check check-normal \
	check-asan install distcheck bench clean distclean

all: build

# Installs the Debian packages that are missing (needs root and apt-get).
deps:
	@missing=""; for p in $(DEB_PACKAGES); do \
	  dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | \
	    grep -q 'install ok installed' || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then \
	  echo "Installing Debian packages:$$missing"; \
	  if [ "$$(id -u)" != 0 ]; then SUDO=sudo; else SUDO=; fi; \
	  $$SUDO apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -qq \
	    --no-install-recommends $$missing >/dev/null || \
	  { echo "error: could not install:$$missing" >&2; exit 1; }; \
	fi

configure: configure.ac Makefile.am $(wildcard */local.mk */*/local.mk)
	autoreconf -fi

bootstrap: deps configure

$(BUILD)/config.status: configure
	mkdir -p $(BUILD)
	cd $(BUILD) && ../configure $(CONFIGURE_FLAGS)

$(ASAN_BUILD)/config.status: configure
	mkdir -p $(ASAN_BUILD)
	cd $(ASAN_BUILD) && ../configure --enable-sanitizers \
	  --disable-shared $(CONFIGURE_FLAGS)

build: deps $(BUILD)/config.status
	$(MAKE) -C $(BUILD) -j$(JOBS)

demo: build
	$(MPIRUN) -n $(NP) $(BUILD)/bin/zrcube scenes/default.pov \
	  +W640 +H480 +A0.3 +WT2 +Odemo.png
	@echo "wrote demo.png"

check: check-normal check-asan

check-normal: build
	$(MAKE) -C $(BUILD) -j$(JOBS) check || \
	  { cat $(BUILD)/test-suite.log; exit 1; }

check-asan: deps $(ASAN_BUILD)/config.status
	$(MAKE) -C $(ASAN_BUILD) -j$(JOBS) check || \
	  { cat $(ASAN_BUILD)/test-suite.log; exit 1; }

install: build
	$(MAKE) -C $(BUILD) install

distcheck: build
	$(MAKE) -C $(BUILD) distcheck

bench: build
	bench/run.sh $(BUILD)
	bench/conformance.sh $(BUILD) all || test $$? = 77

clean:
	-$(MAKE) -C $(BUILD) clean
	-$(MAKE) -C $(ASAN_BUILD) clean

distclean:
	rm -rf $(BUILD) $(ASAN_BUILD) autom4te.cache build-aux aclocal.m4 \
	  configure config.h.in config.h.in~ Makefile.in m4/libtool.m4 \
	  m4/lt*.m4 demo.png

# The library's ABI against the previous release tag (abidiff; see
# tests/abi-check.sh).
.PHONY: abi-check
abi-check: build
	$(MAKE) -C $(BUILD) abi-check
