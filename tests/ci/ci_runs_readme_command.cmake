# Fails unless CI_RUN (.ci/run) runs the command README says CI runs: README's
# "CI (`.ci/run`) runs command (N)." names a line "<command>  # (N) ..." of its first
# ```sh block, and a non-comment line of CI_RUN must be that command (after an "exec ").
# Usage: cmake -DREADME=README.md -DCI_RUN=.ci/run -DSOURCE_DIR=<project> -P this file
file(READ ${README} readme)
if(NOT readme MATCHES "CI \\(`\\.ci/run`\\) runs command \\(([0-9]+)\\)")
  message(FATAL_ERROR "${README} no longer says which of its commands CI runs (\"CI (`.ci/run`) runs command (N).\")")
endif()
set(number ${CMAKE_MATCH_1})
if(NOT readme MATCHES "```sh[^\n]*\n([^`]*)```")
  message(FATAL_ERROR "${README} has no ```sh block of commands")
endif()
set(block "${CMAKE_MATCH_1}")
if(NOT block MATCHES "(^|\n)([^\n#]*[^\n# ]) *# \\(${number}\\)")
  message(FATAL_ERROR "${README}'s first ```sh block has no command marked # (${number})")
endif()
set(command "${CMAKE_MATCH_2}")

if(command MATCHES "(scripts/[^ ]+)")
  set(script ${CMAKE_MATCH_1})
  if(NOT EXISTS ${SOURCE_DIR}/${script})
    message(FATAL_ERROR "README's test command runs ${script}, which does not exist")
  endif()
endif()

file(STRINGS ${CI_RUN} lines)
set(found FALSE)
foreach(line IN LISTS lines)
  string(STRIP "${line}" line)
  string(REGEX REPLACE "^exec +" "" line "${line}")
  if(line STREQUAL command)
    set(found TRUE)
  endif()
endforeach()
if(NOT found)
  # The fixed words first: CMake wraps long messages, and a test matches on them.
  message(FATAL_ERROR "does not run the README's test command: no line of ${CI_RUN} is `${command}`")
endif()
message(STATUS "${CI_RUN} runs the README's command (${number}): ${command}")
