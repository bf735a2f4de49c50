# cmake -DREADME=doc.md -DSOURCE=file.cpp -P CheckQuoted.cmake
# Fails unless the document contains SOURCE's whole text verbatim.
file(READ "${README}" _document)
file(READ "${SOURCE}" _source)
string(FIND "${_document}" "${_source}" _at)
if(_at EQUAL -1)
  message(FATAL_ERROR "${README} does not quote ${SOURCE} verbatim")
endif()
