-- load() takes text only: a binary chunk is refused, and assert turns that into an error.
assert(load("\27Lua", "chunk", "b"))
