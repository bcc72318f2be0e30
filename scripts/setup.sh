#!/usr/bin/env bash
# Installs camlray's toolchain on Debian 12 (bookworm): OCaml 5 and the
# libraries from Debian sid (pinned low, so nothing else is upgraded by
# accident), POV-Ray 3.7 and its examples from bookworm for cross-checks,
# GNU parallel for the render-farm recipe.
# Idempotent: a second run that finds everything in place does nothing.
set -euo pipefail

OCAML_PKGS="ocaml ocaml-dune ocaml-findlib menhir libmenhir-ocaml-dev \
libsedlex-ocaml-dev libdomainslib-ocaml-dev libcmdliner-ocaml-dev \
libalcotest-ocaml-dev libqcheck-ocaml-dev libmulticore-bench-ocaml-dev \
libcamlimages-ocaml-dev libmtime-ocaml-dev libzip-ocaml-dev"
BOOKWORM_PKGS="povray povray-examples povray-includes parallel"

have_ocaml() {
  command -v ocaml >/dev/null 2>&1 &&
    ocaml -version 2>/dev/null | grep -q 'version 5\.' &&
    command -v dune >/dev/null 2>&1 && command -v menhir >/dev/null 2>&1 &&
    for lib in domainslib sedlex cmdliner alcotest qcheck-alcotest \
      multicore-bench camlimages.png camlimages.jpeg camlimages.gif mtime.clock zip; do
      ocamlfind query "$lib" >/dev/null 2>&1 || return 1
    done
}

have_extras() {
  command -v povray >/dev/null 2>&1 && command -v parallel >/dev/null 2>&1 &&
    [ -d /usr/share/doc/povray/examples ] &&
    [ -f /usr/share/povray-3.7/include/colors.inc ]
}

if have_ocaml && have_extras; then
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then SUDO="sudo"; else
    echo "setup: need root (or sudo) to install packages" >&2
    exit 1
  fi
fi
export DEBIAN_FRONTEND=noninteractive

if ! have_ocaml; then
  if [ ! -f /etc/apt/sources.list.d/sid.sources ]; then
    $SUDO tee /etc/apt/sources.list.d/sid.sources >/dev/null <<'SRC'
Types: deb
URIs: http://deb.debian.org/debian
Suites: sid
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SRC
  fi
  if [ ! -f /etc/apt/preferences.d/sid.pref ]; then
    $SUDO tee /etc/apt/preferences.d/sid.pref >/dev/null <<'PREF'
Package: *
Pin: release n=sid
Pin-Priority: 100
PREF
  fi
  $SUDO apt-get update -qq
  # shellcheck disable=SC2086
  $SUDO apt-get install -y -qq -t sid $OCAML_PKGS
fi

if ! have_extras; then
  have_ocaml || true
  $SUDO apt-get update -qq
  # shellcheck disable=SC2086
  $SUDO apt-get install -y -qq $BOOKWORM_PKGS
fi

have_ocaml || { echo "setup: OCaml toolchain still incomplete" >&2; exit 1; }
have_extras || { echo "setup: POV-Ray/parallel still missing" >&2; exit 1; }
echo "setup: toolchain ready ($(ocaml -version))"
