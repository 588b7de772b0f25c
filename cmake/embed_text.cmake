# Turns a text file into a C++ header holding it as a raw string literal (used to embed the
# default machine profile so `drycut run` works with no file on disk, and the report's viewer
# script). DELIM: the raw-string delimiter (default json).
if(NOT DEFINED DELIM)
  set(DELIM json)
endif()
file(READ ${IN} _content)
string(FIND "${_content}" ")${DELIM}\"" _clash)
if(NOT _clash EQUAL -1)
  message(FATAL_ERROR "${IN} contains the raw-string delimiter )${DELIM}\"")
endif()
file(WRITE ${OUT} "// Generated from ${IN}; do not edit.\n#pragma once\ninline constexpr const char* ${VAR} = R\"${DELIM}(${_content})${DELIM}\";\n")
