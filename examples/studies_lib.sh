# Shell functions the study scripts share (sourced by run_studies.sh, seed000_noise.sh and
# seed004_studies.sh; not run on its own).

# col FILE NAME: one column of a sweep.csv by header name (no header). Fails on a failed case.
col() {
  awk -F, -v c="$2" -v f="$1" '
    NR == 1 { for (i = 1; i <= NF; i++) if ($i == c) k = i
              if (!k) { print "no column " c " in " f > "/dev/stderr"; exit 1 }; next }
    $0 !~ /,ok,/ { print "failed case in " f ": " $0 > "/dev/stderr"; exit 1 }
    { print $k }' "$1"
}

# stat DIR CHANNEL KEY: one statistic of a run folder's summary.json (channels.<ch>.<key>).
stat() {
  tr -d ' \n' <"$1/summary.json" |
    sed -E "s/.*\"channels\":\{(.*)\},\"frequencies\".*/\1/" |
    grep -oE "\"$2\":\{[^}]*\}" | grep -oE "\"$3\":[-+0-9.eE]+" | cut -d: -f2
}
