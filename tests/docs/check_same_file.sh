#!/bin/sh
# Usage: check_same_file.sh COPY ORIGINAL
# Passes when COPY is byte for byte ORIGINAL; exits 77 (skipped, saying so)
# when ORIGINAL is absent, e.g. a checkout without ../shared next to it.
copy=$1
original=$2
if [ ! -f "$original" ]; then
    echo "skipped: $original does not exist, so $copy has nothing to be compared with"
    exit 77
fi
if cmp -s "$copy" "$original"; then
    echo "$copy is identical to $original"
    exit 0
fi
echo "$copy differs from $original; copy it again: cp '$original' '$copy'"
diff -u "$original" "$copy" | head -40
exit 1
