from genparams.cmake import cmake_dir

print(cmake_dir())
