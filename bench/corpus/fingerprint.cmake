# Checks that the corpus is the one the figures in docs/benchmarks.md were
# measured on: its SHA-256 against cubics-10k.json.sha256 (sha256sum's
# format, so `sha256sum -c` checks it too). Run by ctest (Corpus.Fingerprint):
#   cmake -DCORPUS=bench/corpus/cubics-10k.json -P bench/corpus/fingerprint.cmake
if(NOT CORPUS)
  message(FATAL_ERROR "fingerprint.cmake: set CORPUS to the corpus file")
endif()
if(NOT EXISTS "${CORPUS}")
  message(FATAL_ERROR "corpus not found: ${CORPUS}")
endif()
file(STRINGS "${CORPUS}.sha256" line LIMIT_COUNT 1)
string(REGEX MATCH "^[0-9a-f]+" want "${line}")
file(SHA256 "${CORPUS}" got)
if(NOT got STREQUAL want)
  message(FATAL_ERROR "${CORPUS}: SHA-256 ${got}, expected ${want} (${CORPUS}.sha256): "
                      "the corpus was changed; the benchmarks' figures and the tests' limits are for the original")
endif()
message(STATUS "corpus fingerprint ${got}: as expected")
