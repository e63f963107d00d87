# cmake -P: the manual page bezcam.1 from the program's own --help: the
# program's (name, synopsis, options) by help2man, each command's whole
# --help (options, notes, examples) as a section COMMANDS, and the program's
# closing example as a section EXAMPLES, both kept as printed.
#   -DEXE=path/to/bezcam -DHELP2MAN=path/to/help2man -DOUT=bezcam.1
function(help_of out)
  execute_process(COMMAND ${EXE} ${ARGN} --help OUTPUT_VARIABLE text RESULT_VARIABLE rc)
  if(rc)
    message(FATAL_ERROR "${EXE} ${ARGN} --help failed: ${rc}")
  endif()
  # The usage line names the program as run: the page names it bezcam.
  string(REPLACE "${EXE}" "bezcam" text "${text}")
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

# roff: text as printed (no filling), a backslash as \e, a line that starts
# with . or ' not taken for a request.
function(verbatim out text)
  string(REPLACE "\\" "\\e" text "${text}")
  string(REGEX REPLACE "\n([.'])" "\n\\\\&\\1" text "\n${text}")
  set(${out} ".nf${text}\n.fi\n" PARENT_SCOPE)
endfunction()

get_filename_component(dir ${OUT} DIRECTORY)
set(work ${dir}/manpage)
file(MAKE_DIRECTORY ${work})
help_of(top)
# The program's help up to its closing example (help2man would fill its
# lines into one paragraph); the example goes to EXAMPLES as printed.
string(FIND "${top}" "\nA drawing to " cut)
if(cut EQUAL -1)
  message(FATAL_ERROR "${EXE} --help has no closing example")
endif()
string(SUBSTRING "${top}" 0 ${cut} head)
string(SUBSTRING "${top}" ${cut} -1 closing)
verbatim(closing "${closing}")
set(include "[EXAMPLES]\n${closing}[COMMANDS]\n")
# The commands, as the program's --help lists them under "Subcommands:".
string(REGEX REPLACE ".*\nSubcommands:\n" "" listing "${head}")
string(REGEX MATCHALL "\n?  [a-z]+ " names "\n${listing}")
foreach(n ${names})
  string(STRIP "${n}" cmd)
  help_of(help ${cmd})
  verbatim(help "${help}")
  string(APPEND include ".SS \"bezcam ${cmd}\"\n${help}")
endforeach()
file(WRITE ${work}/bezcam.1.include "${include}")
# help2man runs a program named bezcam that prints the help above.
execute_process(COMMAND ${EXE} --version OUTPUT_VARIABLE version)
file(WRITE ${work}/help.txt "${head}\n")
file(WRITE ${work}/version.txt "${version}")
file(WRITE ${work}/bezcam "#!/bin/sh\ncase \"$1\" in\n  --help) cat '${work}/help.txt' ;;\n  --version) cat '${work}/version.txt' ;;\nesac\n")
file(CHMOD ${work}/bezcam PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE)
execute_process(COMMAND ${HELP2MAN} --no-info --section 1 --name "exact curves to CNC programs with a proven chord error"
                        --include ${work}/bezcam.1.include --output ${OUT}.tmp ${work}/bezcam
                RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "help2man failed: ${rc}")
endif()
file(RENAME ${OUT}.tmp ${OUT})
