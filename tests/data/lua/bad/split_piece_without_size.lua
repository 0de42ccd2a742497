component { label = "floor", size = { 10, 2.5, 10 } }
for c in query("floor") do
  split(c, "X", { label = "a", rel = 1 }, { label = "b" })
end
