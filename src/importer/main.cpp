// rotinterp-import: the process every assimp import runs in (include/rotinterp/io/process/importer.h).
// read_clip() starts it; it is installed in libexec, not on the PATH.
#include "rotinterp/io/process/importer.h"

int main(int argc, char** argv) { return rotinterp::detail::importer_main(argc, argv); }
