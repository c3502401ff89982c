#!/bin/sh
# Usage: check_xml_wellformed.sh FILE...
# Exit 0 when every FILE is well-formed XML, 1 when one is not, 77 (CTest
# SKIP_RETURN_CODE) when no XML checker is installed.
[ $# -ge 1 ] || { echo "usage: $0 FILE..." >&2; exit 2; }
for f in "$@"; do
  [ -f "$f" ] || { echo "missing: $f" >&2; exit 1; }
done
if command -v xmllint >/dev/null 2>&1; then
  echo "checking with xmllint: $*"
  exec xmllint --noout "$@"
fi
if command -v python3 >/dev/null 2>&1 && python3 -c 'import xml.dom.minidom' >/dev/null 2>&1; then
  echo "xmllint not found; checking with Python's xml.dom.minidom: $*"
  exec python3 -c 'import sys, xml.dom.minidom
for f in sys.argv[1:]:
    xml.dom.minidom.parse(f)
print("well-formed")' "$@"
fi
echo "neither xmllint nor python3 found: skipping"
exit 77
