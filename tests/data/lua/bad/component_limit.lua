component { label = "strip", size = { 1000, 1, 1 } }
for c in query("strip") do
  split(c, "X", { label = "cell", abs = 0.001 }, { label = "cell", abs = 0.001 })
end
for i = 1, 100000 do component { label = "box", size = { 1, 1, 1 } } end
