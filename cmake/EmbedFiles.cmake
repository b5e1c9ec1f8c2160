# foveate_embed_files(<target> <header-name> <base-dir> <files...>)
# Embeds text files (GLSL) into the binary at build time: generates
# <binary-dir>/generated/<header-name>.hpp declaring, in namespace
# foveate::embedded, a table <header-name>() of {name, text} where name is the
# file's path relative to <base-dir>. Nothing is read from disk at run time.
set(FOVEATE_EMBED_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/embed_files_script.cmake)

function(foveate_embed_files target name base)
  set(out_dir ${CMAKE_CURRENT_BINARY_DIR}/generated)
  set(out_hpp ${out_dir}/foveate_embedded/${name}.hpp)
  set(out_cpp ${out_dir}/${name}.cpp)
  set(files ${ARGN})
  add_custom_command(
    OUTPUT ${out_hpp} ${out_cpp}
    COMMAND ${CMAKE_COMMAND} -DNAME=${name} -DBASE=${base} -DOUT_HPP=${out_hpp} -DOUT_CPP=${out_cpp}
            "-DFILES=${files}" -P ${FOVEATE_EMBED_SCRIPT}
    DEPENDS ${files} ${FOVEATE_EMBED_SCRIPT}
    COMMENT "Embedding ${name} shaders"
    VERBATIM)
  target_sources(${target} PRIVATE ${out_cpp} ${out_hpp})
  target_include_directories(${target} PRIVATE ${out_dir})
endfunction()
