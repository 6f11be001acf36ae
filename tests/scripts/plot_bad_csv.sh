# A CSV without fairway's columns is refused with a clear message.
printf 'a,b\n1,2\n' > bad.csv
"$PYTHON" "$ANALYSIS/plot_manoeuvre.py" bad.csv --out plots-bad
