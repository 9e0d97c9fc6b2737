# Embeds every glsl/*.glsl file into a generated C++ source as a raw string, so the library
# never looks shaders up on disk at run time. taa_embed_shaders(<out.cpp> <files...>)
function(taa_embed_shaders out_cpp)
  set(files ${ARGN})
  add_custom_command(
    OUTPUT ${out_cpp}
    COMMAND ${CMAKE_COMMAND} -DOUT=${out_cpp} "-DFILES=${files}"
            -P ${PROJECT_SOURCE_DIR}/cmake/EmbedShadersScript.cmake
    DEPENDS ${files} ${PROJECT_SOURCE_DIR}/cmake/EmbedShadersScript.cmake
    COMMENT "Embedding GLSL shaders"
    VERBATIM)
endfunction()

# Embeds one text file as `const char* <function>()` in <namespace>, declared in <header>.
function(taa_embed_text out_cpp file namespace function header)
  add_custom_command(
    OUTPUT ${out_cpp}
    COMMAND ${CMAKE_COMMAND} -DOUT=${out_cpp} -DFILE=${file} -DNAMESPACE=${namespace}
            -DFUNCTION=${function} -DHEADER=${header}
            -P ${PROJECT_SOURCE_DIR}/cmake/EmbedTextScript.cmake
    DEPENDS ${file} ${PROJECT_SOURCE_DIR}/cmake/EmbedTextScript.cmake
    COMMENT "Embedding ${file}"
    VERBATIM)
endfunction()
