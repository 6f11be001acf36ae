# The turning circle's time history as CSV: header and first rows.
set -e
"$FAIRWAY" manoeuvre turning --ship c3 --speed 26.7 --rudder 35 --side starboard --csv turning.csv > /dev/null
head -n 3 turning.csv
