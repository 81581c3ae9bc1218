# Fails when the repository cites a document it does not hold: a source comment, a CMake file, a
# script or a document naming a repository-relative path such as docs/ERRATA.md that does not
# exist, a Markdown link whose target does not exist, a numbered section ("docs/V2.35.md section
# 4.2", "sections 4.2 and 6", "s.12") the document has no heading for, or a quoted section
# ('docs/ARCHITECTURE.md "Timing model"', 'ERRATA "Generations"') none of its headings names.
# Absolute paths (/usr/share/doc/lkstudio/CLI.md) are runtime paths and are not checked.
#
#   cmake -DSOURCE_DIR=<repository> -P CheckDocCitations.cmake
#   cmake -DSELF_TEST_DIR=<scratch directory> -P CheckDocCitations.cmake
# The second form builds a small tree with known faults there and fails unless the check finds
# exactly those: the check itself can fail.
cmake_minimum_required(VERSION 3.22)

# The files whose citations are checked, relative to `root`.
function(lk_doc_citing_files root out)
    set(patterns "")
    foreach(dir core ui app tests resources packaging)
        foreach(ext cpp h cmake sh md)
            list(APPEND patterns "${root}/${dir}/*.${ext}")
        endforeach()
        list(APPEND patterns "${root}/${dir}/CMakeLists.txt")
    endforeach()
    file(GLOB_RECURSE found RELATIVE "${root}" ${patterns})
    file(GLOB top RELATIVE "${root}" "${root}/CMakeLists.txt" "${root}/README*.md"
         "${root}/.ci/run")
    file(GLOB_RECURSE docs RELATIVE "${root}" "${root}/docs/*.md")
    set(all ${found} ${top} ${docs})
    list(REMOVE_DUPLICATES all)
    # This file cites documents that do not exist on purpose (its self-test).
    list(REMOVE_ITEM all "tests/CheckDocCitations.cmake")
    list(SORT all)
    set(${out} "${all}" PARENT_SCOPE)
endfunction()

# "file:line" of the first occurrence of `needle` in `content`.
function(lk_doc_where file content needle out)
    string(FIND "${content}" "${needle}" at)
    set(line 1)
    if(at GREATER 0)
        string(SUBSTRING "${content}" 0 ${at} before)
        string(REGEX MATCHALL "\n" breaks "${before}")
        list(LENGTH breaks n)
        math(EXPR line "${n} + 1")
    endif()
    set(${out} "${file}:${line}" PARENT_SCOPE)
endfunction()

# The headings of a Markdown file, one string ("\n## 4.2 Title\n..."); empty if it is missing.
function(lk_doc_headings path out)
    set(text "")
    if(EXISTS "${path}" AND NOT IS_DIRECTORY "${path}")
        file(READ "${path}" body)
        string(REGEX MATCHALL "\n#+ [^\n]*" lines "\n${body}")
        string(REPLACE ";" "" text "${lines}")
    endif()
    set(${out} "${text}" PARENT_SCOPE)
endfunction()

# In lk_check_file: unless `target` exists, a problem "<file>:<line>: <what>, which does not
# exist", at the first occurrence of `needle` in `content`.
function(lk_doc_require target what needle)
    if(NOT EXISTS "${target}")
        lk_doc_where("${file}" "${content}" "${needle}" where)
        list(APPEND problems "${where}: ${what}, which does not exist")
        set(problems "${problems}" PARENT_SCOPE)
    endif()
endfunction()

# Appends to `problems` (in the caller) every citation of `file` (relative to `root`) that
# points at nothing.
function(lk_check_file root file)
    set(problems "${problems}")
    file(READ "${root}/${file}" content)
    get_filename_component(dir "${root}/${file}" DIRECTORY)
    string(REGEX MATCH "[.]md$" markdown "${file}")
    # Square brackets and semicolons have a meaning in CMake lists: the text searched has none
    # (a Markdown link "[text](target)" becomes " text @link(target)").
    string(REPLACE "](" " @link(" text " ${content}")
    foreach(c "[" "]" ";")
        string(REPLACE "${c}" " " text "${text}")
    endforeach()

    # Markdown links resolve against the document's own folder; web links are not ours.
    if(markdown)
        string(REGEX MATCHALL "@link[(][^)\n]+[)]" links "${text}")
        foreach(link IN LISTS links)
            string(REGEX REPLACE "^@link[(]([^ )#]*).*" "\\1" target "${link}")
            if(target STREQUAL "" OR target MATCHES "^[a-zA-Z][a-zA-Z+.-]*:" OR target MATCHES "^/")
                continue()
            endif()
            lk_doc_require("${dir}/${target}" "link to ${target}" "](${target}")
        endforeach()
        # What remains is prose: its paths are repository-relative.
        string(REGEX REPLACE "@link[(][^)\n]*[)]" " " text "${text}")
    endif()

    # Paths written relative to the source tree through a variable are repository-relative too.
    foreach(prefix "\${PROJECT_SOURCE_DIR}/" "\${CMAKE_SOURCE_DIR}/" "LK_SOURCE_DIR \"/")
        string(REPLACE "${prefix}" " " text "${text}")
    endforeach()
    # A relative path with a folder (docs/CLI.md), or one of the READMEs at the top. The
    # character before it may not belong to a path: /usr/share/doc/lkstudio/CLI.md is skipped.
    string(REGEX MATCHALL "[^A-Za-z0-9_./~$-][A-Za-z0-9_][A-Za-z0-9_.-]*(/[A-Za-z0-9_.-]+)+\\.md"
           paths "${text}")
    string(REGEX MATCHALL "[^A-Za-z0-9_./~$-]README[A-Za-z0-9_.-]*\\.md" readmes "${text}")
    set(seen "")
    foreach(match IN LISTS paths readmes)
        string(SUBSTRING "${match}" 1 -1 path)
        if(path IN_LIST seen)
            continue()
        endif()
        list(APPEND seen "${path}")
        # A path inside an installed system (check-deb.sh: usr/share/doc/lkstudio/CLI.md).
        if(NOT path MATCHES "^(usr|etc|var|opt|lib|run|tmp|home)/")
            lk_doc_require("${root}/${path}" "cites ${path}" "${path}")
        endif()
    endforeach()

    # Section citations may wrap onto the next comment line: drop the comment markers that
    # start a line (the line breaks stay, so that line numbers still hold).
    string(REGEX REPLACE "\n[ \t]*(//+|#+|\\*)[ \t]*" "\n" joined "${text}")
    string(REGEX MATCHALL
           "docs/[A-Za-z0-9_.-]+\\.md,?[ \n]+(sections?|s\\.)[ \n]*[0-9]+(\\.[0-9]+)?(([ \n]*,[ \n]*|[ \n]+and[ \n]+|[ \n]+or[ \n]+)[0-9]+(\\.[0-9]+)?)*"
           numbered "${joined}")
    list(REMOVE_DUPLICATES numbered)
    foreach(citation IN LISTS numbered)
        string(REGEX REPLACE "^(docs/[A-Za-z0-9_.-]+\\.md).*" "\\1" path "${citation}")
        string(REGEX REPLACE "^docs/[A-Za-z0-9_.-]+\\.md,?[ \n]+(sections?|s\\.)[ \n]*" "" rest
               "${citation}")
        string(REGEX MATCHALL "[0-9]+(\\.[0-9]+)?" numbers "${rest}")
        if(NOT EXISTS "${root}/${path}")
            continue() # already reported as a missing path
        endif()
        lk_doc_headings("${root}/${path}" headings)
        string(REGEX MATCHALL "\n#+ +[0-9]+(\\.[0-9]+)*" numberedHeadings "${headings}")
        set(have "")
        foreach(h IN LISTS numberedHeadings)
            string(REGEX REPLACE "^\n#+ +" "" h "${h}")
            list(APPEND have "${h}")
        endforeach()
        foreach(n IN LISTS numbers)
            if(NOT n IN_LIST have)
                lk_doc_where("${file}" "${joined}" "${citation}" where)
                list(APPEND problems "${where}: cites ${path} section ${n}, which it has not")
            endif()
        endforeach()
    endforeach()

    # Quoted section names: docs/NAME.md "Title", or NAME "Title" where docs/NAME.md exists.
    string(REGEX MATCHALL "(docs/)?[A-Za-z0-9_.-]+[ \n]\"[^\"\n]+\"" quoted "${joined}")
    list(REMOVE_DUPLICATES quoted)
    foreach(citation IN LISTS quoted)
        string(REGEX REPLACE "^((docs/)?[A-Za-z0-9_.-]+)[ \n]\"([^\"]+)\"$" "\\1" name "${citation}")
        string(REGEX REPLACE "^((docs/)?[A-Za-z0-9_.-]+)[ \n]\"([^\"]+)\"$" "\\3" title "${citation}")
        string(REGEX REPLACE "^docs/" "" base "${name}")
        string(REGEX REPLACE "\\.md$" "" base "${base}")
        if(NOT base MATCHES "^[A-Z]" OR NOT EXISTS "${root}/docs/${base}.md")
            continue() # not a document of ours (a missing docs/ path is reported above)
        endif()
        lk_doc_headings("${root}/docs/${base}.md" headings)
        string(FIND "${headings}" "${title}" found)
        if(found EQUAL -1)
            lk_doc_where("${file}" "${joined}" "${citation}" where)
            list(APPEND problems "${where}: cites \"${title}\" in docs/${base}.md, which has no such heading")
        endif()
    endforeach()
    set(problems "${problems}" PARENT_SCOPE)
endfunction()

# Every problem of the tree at `root`, in file order.
function(lk_check_doc_citations root out count)
    lk_doc_citing_files("${root}" files)
    set(problems "")
    foreach(file IN LISTS files)
        lk_check_file("${root}" "${file}")
    endforeach()
    list(LENGTH files n)
    set(${out} "${problems}" PARENT_SCOPE)
    set(${count} ${n} PARENT_SCOPE)
endfunction()

if(SELF_TEST_DIR)
    # A tree with one citation of each kind that resolves, and one of each kind that does not.
    set(t "${SELF_TEST_DIR}/doc-citations-selftest")
    file(REMOVE_RECURSE "${t}")
    file(WRITE "${t}/docs/Real.md"
         "# Real\n\n## 1. One\n\n### 4.2 Two\n\n## Timing model: the figures\n\n"
         "[ok](Other.md) [gone](Gone.md) [web](https://example.org/x.md) [here](#one)\n")
    file(WRITE "${t}/docs/Other.md" "# Other\n\nSee docs/Real.md and [back](../README.md).\n")
    file(WRITE "${t}/README.md" "[a](docs/Real.md) [b](docs/Nowhere.md)\nREADME.zh_CN.md\n")
    file(WRITE "${t}/core/a.cpp"
         "// docs/Real.md section 4.2 and docs/Real.md sections 1 and 4.2, docs/Real.md s.1\n"
         "// docs/Real.md \"Timing model\", Real \"Timing model\", /usr/share/doc/x/Runtime.md\n"
         "// docs/Missing.md\n"
         "// docs/Real.md section\n"
         "//   7 wraps onto the next line\n"
         "// docs/Real.md \"No such heading\"\n")
    file(WRITE "${t}/CMakeLists.txt" "# docs/Real.md\ninstall(FILES \${PROJECT_SOURCE_DIR}/docs/Lost.md)\n")
    lk_check_doc_citations("${t}" got n)
    set(expected
        "CMakeLists.txt:2: cites docs/Lost.md, which does not exist"
        "README.md:1: link to docs/Nowhere.md, which does not exist"
        "README.md:2: cites README.zh_CN.md, which does not exist"
        "core/a.cpp:3: cites docs/Missing.md, which does not exist"
        "core/a.cpp:4: cites docs/Real.md section 7, which it has not"
        "core/a.cpp:6: cites \"No such heading\" in docs/Real.md, which has no such heading"
        "docs/Real.md:9: link to Gone.md, which does not exist")
    if(NOT got STREQUAL expected)
        string(REPLACE ";" "\n  " got "${got}")
        string(REPLACE ";" "\n  " expected "${expected}")
        message(FATAL_ERROR "the citation check found:\n  ${got}\nexpected:\n  ${expected}")
    endif()
    file(REMOVE_RECURSE "${t}")
    message(STATUS "the citation check finds each kind of broken citation in a tree of ${n} files")
    return()
endif()

if(NOT SOURCE_DIR)
    message(FATAL_ERROR "usage: cmake -DSOURCE_DIR=<repository> -P CheckDocCitations.cmake")
endif()
lk_check_doc_citations("${SOURCE_DIR}" problems n)
if(problems)
    list(LENGTH problems k)
    string(REPLACE ";" "\n" problems "${problems}")
    message(FATAL_ERROR "${k} citation(s) point at nothing in the repository:\n${problems}")
endif()
message(STATUS "checked the document citations of ${n} files: every one resolves")
