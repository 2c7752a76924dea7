# Fails if FILE names a file format: the clip model (clip/clip.h) holds none, a
# format's own data travels in the clip's opaque record (clip/source_record.h).
# Usage: cmake -DFILE=<header> -P this file
file(READ ${FILE} text)
string(TOLOWER "${text}" text)
foreach(format bvh fbx gltf glb collada dae assimp)
  if(text MATCHES "(^|[^a-z_])${format}([^a-z_]|$)")
    message(FATAL_ERROR "names a file format, '${format}': ${FILE}")
  endif()
endforeach()
