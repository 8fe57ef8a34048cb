# Doxygen's INPUT_FILTER (Doxyfile): reads the public headers' plain // comments as
# documentation, line for line (the line numbers stay). The top block, just above
# `#pragma once`, is the file's description; a comment block above a declaration documents
# it; a comment after a member on its line (with the lines continuing it in the same column)
# documents that member. Comments inside function bodies stay plain comments. The text is
# plain, not Doxygen markup: \ @ < > % # & are escaped, but in "quoted text" and `code`,
# which Doxygen shows as written.
function plain(text,   out, i, c) {
  out = ""
  for (i = 1; i <= length(text); i++) {
    c = substr(text, i, 1)
    if (c == "\"" && !code) quoted = !quoted
    else if (c == "`" && !quoted) code = !code
    else if (!quoted && !code && index("\\@<>%#&", c)) c = "\\" c
    out = out c
  }
  return out
}
/^#pragma once$/ { print "/// \\file"; next }
{
  text = $0
  sub(/[ \t]*\/\/.*/, "", text)
  opens = gsub(/{/, "{", text)
  closes = gsub(/}/, "}", text)
  if (body > 0) {  # inside a function body: as it is
    body += opens - closes
    print; next
  }
  if (text ~ /\)/ && opens > closes) body = opens - closes  # a body opens on this line
  if (text ~ /^[ \t]*$/ && match($0, /^[ \t]*\/\//)) {  # a comment line
    at = index($0, "//")
    print substr($0, 1, at - 1) (at == trailing ? "///<" : "///") plain(substr($0, at + 2))
    next
  }
  trailing = 0
  quoted = code = 0  # a new comment starts outside quotes and code
  if (text !~ /^[ \t]*([{}][;}]*|#.*)$/ && match($0, /[^ \t][ \t]+\/\/ /)) {
    trailing = index(substr($0, RSTART + 1), "//") + RSTART
    $0 = substr($0, 1, trailing - 1) "///<" plain(substr($0, trailing + 2))
  }
  print
}
