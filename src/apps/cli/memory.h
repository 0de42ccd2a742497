// Giving memory back between the stages of a long job (issue 17: a city's peak memory).
#pragma once

namespace insula::cli {

// Returns the allocator's free pages to the system. tcmalloc (CMakeLists.txt) keeps what a stage
// freed for later reuse; a later stage that allocates differently would add to it, so a job calls
// this where one stage's working memory ends (the reader's, before the buildings are made).
// Nothing to do with other allocators.
void release_free_memory();

// Asks the allocator to take its memory from the system in blocks the kernel may back with huge
// pages: fewer first-touch page faults, which are dear on virtual machines. Called once, first
// thing in main. Nothing to do with other allocators.
void use_huge_pages();

}  // namespace insula::cli
