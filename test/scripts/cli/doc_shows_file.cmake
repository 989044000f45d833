# SPDX-License-Identifier: BSD-3-Clause
# Checks that the markdown file DOC shows the file FILE verbatim in a fenced code block, so that the file a test
# runs and the text a reader copies are one: cmake -DDOC=doc.md -DFILE=script -P doc_shows_file.cmake
file(READ "${DOC}" doc)
file(READ "${FILE}" content)
string(FIND "${doc}" "```bash\n${content}```\n" at)
if(at EQUAL -1)
  get_filename_component(name "${FILE}" NAME)
  message(FATAL_ERROR "${DOC} does not show ${FILE} as it is (a ```bash block holding exactly its text): "
                      "paste the file into the block after \"${name}\"")
endif()
message(STATUS "${DOC} shows ${FILE} as it is")
