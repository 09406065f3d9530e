#!/bin/sh
# Doxygen's FILTER_PATTERNS for headers (docs/api/Doxyfile.in): a header's plain "// "
# comments are its documentation. A comment line becomes "/// ", and a comment after a
# declaration on the same line ("int x;  // ...") becomes "///< ", which documents that
# member. A header's opening comment documents the file, not the first declaration below
# it. ('#' delimits the expressions, so that "\|" means "or".)
exec sed -e '1s#^// #/// \\file\n/// #' \
         -e '2,$s#^\([[:space:]]*\)//\( \|$\)#\1///\2#' \
         -e 's#\([;,{]\)\([[:space:]]*\)// #\1\2///< #' "$1"
