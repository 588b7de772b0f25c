# Turns a text file into a C++ header holding it as a raw string literal (used to embed the
# default machine profile so `drycut run` works with no file on disk).
file(READ ${IN} _content)
string(FIND "${_content}" ")json\"" _clash)
if(NOT _clash EQUAL -1)
  message(FATAL_ERROR "${IN} contains the raw-string delimiter )json\"")
endif()
file(WRITE ${OUT} "// Generated from ${IN}; do not edit.\n#pragma once\ninline constexpr const char* ${VAR} = R\"json(${_content})json\";\n")
