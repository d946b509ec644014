# Every relative link in README.md, docs/*.md and constraints/*.md resolves: the file exists and,
# for a link with #anchor into a Markdown file, that file has a heading with that anchor (GitHub's
# rule: lower case, punctuation dropped, spaces to hyphens). Links in code are not links. First
# the checker must find both faults planted in a page of its own. Run by ctest with SOURCE_DIR and
# WORK set.
cmake_policy(VERSION 3.16)  # IN_LIST
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

# The page's text without code: fenced blocks, then inline code spans.
function(prose_of file out_var)
  file(READ ${file} text)
  string(REGEX REPLACE "```[^`]*```" "" text "${text}")
  string(REGEX REPLACE "`[^`\n]*`" "" text "${text}")
  set(${out_var} "${text}" PARENT_SCOPE)
endfunction()

# The anchors of a Markdown file's headings (code spans in a heading count for its anchor).
function(anchors_of file out_var)
  file(READ ${file} text)
  string(REGEX REPLACE "```[^`]*```" "" text "${text}")
  string(REGEX REPLACE "[][;]" "" text "\n${text}")
  string(REGEX MATCHALL "\n#+ [^\n]*" headings "${text}")
  set(anchors "")
  foreach(heading IN LISTS headings)
    string(REGEX REPLACE "^\n#+ " "" title "${heading}")
    string(TOLOWER "${title}" slug)
    string(REGEX REPLACE "[^a-z0-9 _-]" "" slug "${slug}")
    string(REPLACE " " "-" slug "${slug}")
    list(APPEND anchors "${slug}")
  endforeach()
  set(${out_var} "${anchors}" PARENT_SCOPE)
endfunction()

# Appends to the list errors_var one line per link of file that does not resolve.
function(check_links file errors_var)
  set(errors ${${errors_var}})
  prose_of(${file} text)
  get_filename_component(dir ${file} DIRECTORY)
  # "](" becomes "<link>(": a bracket in a list element would make CMake join elements.
  string(REPLACE "](" "<link>(" text "${text}")
  string(REGEX MATCHALL "<link>\\([^) ;\n]+\\)" links "${text}")
  foreach(link IN LISTS links)
    string(REGEX REPLACE "^<link>\\((.*)\\)$" "\\1" target "${link}")
    if(target MATCHES "^[a-z]+:")
      continue()  # http:, https:, mailto:
    endif()
    string(REGEX REPLACE "#.*$" "" path "${target}")
    set(anchor "")
    if(target MATCHES "#(.*)$")
      set(anchor "${CMAKE_MATCH_1}")
    endif()
    if(path STREQUAL "")
      set(resolved ${file})
    else()
      get_filename_component(resolved "${dir}/${path}" ABSOLUTE)
    endif()
    if(NOT EXISTS "${resolved}")
      list(APPEND errors "${file}: link (${target}): no file ${resolved}")
    elseif(NOT anchor STREQUAL "" AND resolved MATCHES "\\.md$")
      anchors_of("${resolved}" anchors)
      if(NOT anchor IN_LIST anchors)
        list(APPEND errors "${file}: link (${target}): no heading with anchor #${anchor} in ${resolved}")
      endif()
    endif()
  endforeach()
  set(${errors_var} "${errors}" PARENT_SCOPE)
endfunction()

# The checker itself: a page with one good link and two broken ones must give exactly two errors.
file(WRITE ${WORK}/planted.md "# A page\n\n## Some `code` here, too\n\n"
  "[good](#some-code-here-too), [no file](missing.md), [no heading](planted.md#nowhere),\n"
  "`[in code](missing-too.md)`\n")
set(planted "")
check_links(${WORK}/planted.md planted)
list(LENGTH planted count)
if(NOT count EQUAL 2)
  string(REPLACE ";" "\n" planted "${planted}")
  message(FATAL_ERROR "doc_links: the checker found ${count} broken links in the planted page, not 2:\n${planted}")
endif()

file(GLOB pages ${SOURCE_DIR}/README.md ${SOURCE_DIR}/docs/*.md ${SOURCE_DIR}/constraints/*.md)
set(errors "")
foreach(page IN LISTS pages)
  check_links(${page} errors)
endforeach()
if(errors)
  string(REPLACE ";" "\n" errors "${errors}")
  message(FATAL_ERROR "doc_links: links that do not resolve:\n${errors}")
endif()
list(LENGTH pages n)
message(STATUS "doc_links: every relative link of ${n} pages resolves")
