# Video painter benches (bench/video_bench.sh drives them).
add_executable(video_encode ${CMAKE_CURRENT_LIST_DIR}/video_encode.cpp)
target_link_libraries(video_encode PRIVATE spt_video)
add_executable(video_coherence ${CMAKE_CURRENT_LIST_DIR}/video_coherence.cpp)
target_link_libraries(video_coherence PRIVATE spt_video)  # for its OpenCV usage requirements
