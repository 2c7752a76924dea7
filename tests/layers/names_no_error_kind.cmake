# Fails if FILE names an error kind of io: core's ErrorKind is open and names only
# `other` (core/result.h); the kinds are the io layers' own. KINDS: the headers that
# define them, read for their names, so that a new kind is checked with no list here.
# Usage: cmake -DFILE=<file> "-DKINDS=<header>;<header>" -P this file
set(names)
foreach(header IN LISTS KINDS)
  file(STRINGS ${header} lines REGEX "constexpr ErrorKind [a-z_]+{")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE ".*constexpr ErrorKind ([a-z_]+){.*" "\\1" name "${line}")
    list(APPEND names ${name})
  endforeach()
endforeach()
if(NOT names)
  message(FATAL_ERROR "found no error kind in ${KINDS}")
endif()
file(READ ${FILE} text)
foreach(name IN LISTS names)
  if(text MATCHES "(^|[^a-z_])${name}([^a-z_]|$)")
    message(FATAL_ERROR "names an error kind of io, '${name}': ${FILE}")
  endif()
endforeach()
