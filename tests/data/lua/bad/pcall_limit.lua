-- A limit stops the program for good: pcall cannot catch it.
local ok = pcall(function() while true do end end)
print(ok)
