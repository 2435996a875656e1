# landsim_embed_file(OUT_CPP INPUT SYMBOL NAMESPACE)
# Generates a .cpp defining `extern const std::string_view <NAMESPACE>::<SYMBOL>` holding the
# bytes of INPUT, so that data (the default scene's elevation grid) ships inside the program.
function(landsim_embed_file out_cpp input symbol ns)
  set(script ${CMAKE_SOURCE_DIR}/cmake/EmbedFileScript.cmake)
  add_custom_command(
    OUTPUT ${out_cpp}
    COMMAND ${CMAKE_COMMAND} -DINPUT=${input} -DOUTPUT=${out_cpp} -DSYMBOL=${symbol}
            -DNAMESPACE=${ns} -P ${script}
    DEPENDS ${input} ${script}
    COMMENT "Embedding ${input}"
    VERBATIM)
endfunction()

# landsim_embed_files(OUT_LIST NAMESPACE BASE "relative/path|Symbol" ...): landsim_embed_file
# for each pair (a path relative to BASE and the symbol that holds it); the generated sources
# are returned in OUT_LIST.
function(landsim_embed_files out_list ns base)
  set(sources "")
  foreach(pair ${ARGN})
    string(REPLACE "|" ";" parts "${pair}")
    list(GET parts 0 relative)
    list(GET parts 1 symbol)
    set(out ${CMAKE_CURRENT_BINARY_DIR}/embedded_${symbol}.cpp)
    landsim_embed_file(${out} ${base}/${relative} ${symbol} ${ns})
    list(APPEND sources ${out})
  endforeach()
  set(${out_list} ${sources} PARENT_SCOPE)
endfunction()
