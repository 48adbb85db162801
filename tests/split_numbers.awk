# split_numbers.awk — finds numbers cut across two lines in `pdftotext
# -layout` output: prints "LINE: first | second" for each and exits 1 if
# any.  A table cell that wraps continues on the next line in its own
# column, so a cut number shows as two tokens in overlapping columns of
# consecutive lines:
#   - "3340" over ".2" (the second piece starts with the decimal point),
#   - "3340." over "2" (the first piece is a number ending with it; list
#     numbers "1." over "2." are not numbers cut),
#   - a line's last token, a number, over the next line's first token
#     starting with a digit (a digit at a cell's line end followed by a
#     digit at its next line's start), where the first line holds more
#     than that token (a table row has its other cells): a lone number
#     over a number is a column of figure labels (a stacked bar's
#     segments), not a table cell.
# Table rows of whole numbers never match: the pieces above must overlap
# in columns and the third rule compares a last token with a first one.

# Splits line s into tokens: their text, first and last column (1-based).
function tokens(s, txt, lo, hi,    n, i, c, inside) {
	n = 0
	inside = 0
	for (i = 1; i <= length(s); i++) {
		c = substr(s, i, 1)
		if (c != " " && !inside) {
			n++
			lo[n] = i
			txt[n] = c
			inside = 1
		} else if (c != " ") {
			txt[n] = txt[n] c
		} else if (inside) {
			hi[n] = i - 1
			inside = 0
		}
	}
	if (inside)
		hi[n] = length(s)
	return n
}

function overlap(a0, a1, b0, b1) {
	return a0 <= b1 && b0 <= a1
}

{
	# Form feeds start pages; they are not text.
	gsub(/\f/, "")
	n2 = tokens($0, t2, l2, h2)
	if (NR > 1) {
		for (i = 1; i <= n1; i++) {
			for (j = 1; j <= n2; j++) {
				if (!overlap(l1[i], h1[i], l2[j], h2[j]))
					continue
				cut = (t1[i] ~ /[0-9]$/ && t2[j] ~ /^[.,][0-9]/) ||
				      (t1[i] ~ /^[0-9][0-9,]*\.$/ && t2[j] ~ /^[0-9]/ && t2[j] !~ /^[0-9]+\.$/) ||
				      (i == n1 && j == 1 && n1 > 1 &&
				       t1[i] ~ /^[0-9]([0-9.,]*[0-9])?$/ && t2[j] ~ /^[0-9]/)
				if (cut) {
					printf "%d: %s | %s\n", NR, t1[i], t2[j]
					bad = 1
				}
			}
		}
	}
	n1 = n2
	for (j = 1; j <= n2; j++) {
		t1[j] = t2[j]
		l1[j] = l2[j]
		h1[j] = h2[j]
	}
}

END { exit bad }
