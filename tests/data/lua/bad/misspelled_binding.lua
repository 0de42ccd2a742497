-- A typo in a binding name.
component { label = "lot", size = { 10, 3, 8 } }
for c in query("lot") do
  splt(c, "X", { label = "a", rel = 1 })
end
