# catena_embed_file(<target> <function> <path>): adds to <target> a function
# `std::string_view catena::cli::<function>()` returning the bytes of <path>, embedded at build
# time (GNU assembler .incbin); rebuilt when the file changes.
function(catena_embed_file target function path)
  if(NOT EXISTS "${path}")
    message(FATAL_ERROR "catena: ${path} is missing. Run scripts/setup.sh (it installs the npm "
                        "packages of web/ as well as the Debian packages).")
  endif()
  set(EMBED_PATH "${path}")
  set(EMBED_SYMBOL "catena_embedded_${function}")
  set(EMBED_FUNCTION "${function}")
  set(generated "${CMAKE_CURRENT_BINARY_DIR}/embedded_${function}.cpp")
  configure_file("${PROJECT_SOURCE_DIR}/cmake/embed_file.cpp.in" "${generated}" @ONLY)
  set_source_files_properties("${generated}" PROPERTIES OBJECT_DEPENDS "${path}")
  target_sources(${target} PRIVATE "${generated}")
endfunction()
