# cmake -DIN=file -DOUT=file.gz -P gzip_file.cmake: a gzip stream of one file (the
# self-contained page carries the module gzipped; browsers inflate it with DecompressionStream).
file(ARCHIVE_CREATE OUTPUT ${OUT}.tmp PATHS ${IN} FORMAT raw COMPRESSION GZip COMPRESSION_LEVEL 9)
file(RENAME ${OUT}.tmp ${OUT})
