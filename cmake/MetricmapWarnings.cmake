# One place for warnings and optional instrumentation, applied per target.
function(metricmap_set_warnings target)
  target_compile_options(${target} PRIVATE
    $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wpedantic -Wno-unused-parameter>)
  if(METRICMAP_SANITIZE)
    target_compile_options(${target} PRIVATE -fsanitize=address,undefined -fno-omit-frame-pointer
                                             -fno-sanitize-recover=undefined)
    target_link_options(${target} PRIVATE -fsanitize=address,undefined)
    # Eigen switches to its own offset-based aligned malloc under ASan; the prebuilt PCL
    # libraries use glibc's (already 16-byte aligned) malloc, so memory allocated in one and
    # freed in the other trips ASan (PCL issue #5457 shows the same stack). Keep them in step.
    target_compile_definitions(${target} PRIVATE EIGEN_MALLOC_ALREADY_ALIGNED=1)
  endif()
  if(METRICMAP_TSAN)
    target_compile_options(${target} PRIVATE -fsanitize=thread -fno-omit-frame-pointer)
    target_link_options(${target} PRIVATE -fsanitize=thread)
  endif()
  if(METRICMAP_NATIVE)
    target_compile_options(${target} PRIVATE -march=native)
  endif()
endfunction()
