// The failure kinds of reading and writing files, which every io target meets. Core
// only knows that an error has a kind (ErrorKind, core/result.h); io names its
// kinds where they arise: these here, below every format and reader, and the
// importer process's in io/process/process_errors.h. Codes are unique across both
// (process_errors.h, which sees both, checks it when it compiles).
#pragma once

#include "rotinterp/core/result.h"

namespace rotinterp::file_error {

inline constexpr ErrorKind unreadable{1};     // input that is not what it should be: empty, malformed, or refused
inline constexpr ErrorKind no_animation{2};   // readable input that holds no animation (a mesh)
inline constexpr ErrorKind no_file{3};        // nothing at the path: missing, a link to nothing, a loop of links
inline constexpr ErrorKind directory{4};      // the path is a directory
inline constexpr ErrorKind cannot_open{5};    // the system refuses to read it: permissions, not a regular file, I/O
inline constexpr ErrorKind out_of_memory{6};  // the reading needed more memory than the process may have
inline constexpr ErrorKind cannot_write{7};   // an output could not be made (its folder, its file, its lock): the message names it

// Every kind above: what an importer may send back (clip_wire.cpp checks a kind it receives).
inline constexpr ErrorKind all[] = {unreadable, no_animation, no_file, directory, cannot_open, out_of_memory, cannot_write};

}  // namespace rotinterp::file_error
