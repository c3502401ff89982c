#!/bin/sh
# Check scene decks: `raccord --check` must accept each one, and the slave and
# master of every &contact_pair must be physical curves of the deck's Gmsh mesh
# (the model builder does not look at contact pairs yet).
# usage: check_decks.sh [RACCORD] DECK...   (RACCORD defaults to build-scenes/raccord)
# Prints one line per deck: steps, dt, estimated time, contact pairs.
here=$(cd "$(dirname "$0")" && pwd)
exe=$here/../../build-scenes/raccord
case "$1" in *raccord) exe=$1; shift ;; esac
status=0
for deck in "$@"; do
  out=$("$exe" --check "$deck" 2>&1) || { echo "FAIL $deck"; echo "$out" | grep -v '^ ' | head -5; status=1; continue; }
  mesh=$(echo "$out" | sed -n "s/^  file = '\(.*\)'$/\1/p" | head -1)
  pairs=""
  for name in $(sed -n "s/.*\(slave\|master\) *= *'\([^']*\)'.*/\2/p" "$deck"); do
    if ! grep -q "^1 [0-9]* \"$name\"$" "$mesh"; then
      echo "FAIL $deck: contact surface '$name' is not a physical curve of $mesh"; status=1
    fi
  done
  pairs=$(sed -n "s/.*slave *= *'\([^']*\)', *master *= *'\([^']*\)'.*/\1->\2/p" "$deck" | tr '\n' ' ')
  t=$(echo "$out" | sed -n 's/^time .*stable dt = \([^,]*\), dt = \([^ ]*\) .*, \([0-9]*\) steps/dt=\2 steps=\3/p')
  c=$(echo "$out" | sed -n 's/^cost .*estimated run time \([^ ]*\) s.*/est=\1s/p')
  m=$(echo "$out" | sed -n 's/^mesh .*: \([0-9]*\) nodes, \([0-9]*\) elements/nodes=\1 elems=\2/p')
  echo "ok   $(basename "$deck") $m $t $c pairs: $pairs"
done
exit $status
