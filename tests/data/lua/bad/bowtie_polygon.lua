component { label = "lot", polygon = { { 0, 0 }, { 4, 4 }, { 4, 0 }, { 0, 4 } } }
