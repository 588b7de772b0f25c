# Writes the man page drycut.1 from the built binary's own help (`drycut --help` and
# `drycut COMMAND --help` for every subcommand), so the page never disagrees with the program.
# With help2man (Debian package help2man) it formats the page; without it, a plain roff page is
# written here from the same text.
#   cmake -DDRYCUT=<binary> -DOUT=<drycut.1> [-DHELP2MAN=<help2man>] -P make_man_page.cmake
execute_process(COMMAND ${DRYCUT} --help OUTPUT_VARIABLE _main RESULT_VARIABLE _rc)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "${DRYCUT} --help failed")
endif()
execute_process(COMMAND ${DRYCUT} --version OUTPUT_VARIABLE _version OUTPUT_STRIP_TRAILING_WHITESPACE)
# Subcommands: the lines "  name   description" under "Subcommands:" of the main help.
string(REGEX REPLACE ".*[Ss][Uu][Bb][Cc][Oo][Mm][Mm][Aa][Nn][Dd][Ss]:\n" "" _subs "${_main}")
string(REGEX MATCHALL "\n  [a-z]+ " _names "\n${_subs}")
set(_commands "")
foreach(_n IN LISTS _names)
  string(STRIP "${_n}" _n)
  execute_process(COMMAND ${DRYCUT} ${_n} --help OUTPUT_VARIABLE _help)
  string(APPEND _commands ".SS \"drycut ${_n}\"\n.nf\n${_help}.fi\n")
endforeach()
string(REPLACE "\\" "\\\\" _commands "${_commands}")
if(HELP2MAN)
  file(WRITE ${OUT}.include "[COMMANDS]\n${_commands}\n[SEE ALSO]\nThe documentation in share/doc/drycut (README.md, docs/guide.md).\n")
  execute_process(COMMAND ${HELP2MAN} --no-info --section=1 --name=dry-run\ SINUMERIK\ 840D\ part\ programs
                          --include=${OUT}.include --output=${OUT} ${DRYCUT} RESULT_VARIABLE _rc)
  file(REMOVE ${OUT}.include)
  if(_rc EQUAL 0)
    return()
  endif()
  message(WARNING "help2man failed; writing the plain page")
endif()
string(REPLACE "\\" "\\\\" _main "${_main}")
file(WRITE ${OUT} ".TH DRYCUT 1 \"\" \"${_version}\" \"User Commands\"\n"
                  ".SH NAME\ndrycut \\- dry-run SINUMERIK 840D part programs before cutting metal\n"
                  ".SH SYNOPSIS\n.B drycut\n[\\fIOPTIONS\\fR] \\fICOMMAND\\fR ...\n"
                  ".SH DESCRIPTION\n.nf\n${_main}.fi\n.SH COMMANDS\n${_commands}"
                  ".SH SEE ALSO\nThe documentation in share/doc/drycut (README.md, docs/guide.md).\n")
