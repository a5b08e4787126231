# INPUT_FILTER of the API reference (Doxyfile.in): Doxygen ends a brief description at
# the first ". ", so "Fig. 1", "e.g. a" and "i.e. b" would cut it short. Escaping the
# space ("Fig.\ 1") keeps the sentence whole; the headers themselves stay plain.
s/\(Fig\|e\.g\|i\.e\)\. /\1.\\ /g
s/\(Trans\)\. /\1.\\ /g
# An author's initial ("C. Schlick").
s/\([ (][A-Z]\)\. \([A-Z][a-z]\)/\1.\\ \2/g
