split("floor", "X", { label = "a", rel = 1 })
