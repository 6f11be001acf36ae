# The manoeuvring report's histories drawn as PNG sheets; prints each file's size.
set -e
rm -rf plots && mkdir -p plots
"$FAIRWAY" manoeuvre report --ship c3 --csv-dir plots > /dev/null
"$PYTHON" "$ANALYSIS/plot_manoeuvre.py" plots/*.csv --trial c3 --out plots > /dev/null
for f in plots/*.png; do echo "$(basename "$f") $(stat -c %s "$f") bytes"; done
