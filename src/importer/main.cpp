// rotinterp-import: the process every assimp import runs in (src/io/import.h).
// read_clip() starts it; it is installed in libexec, not on the PATH.
#include "import.h"

int main(int argc, char** argv) { return rotinterp::detail::importer_main(argc, argv); }
