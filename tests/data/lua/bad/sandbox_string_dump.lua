local bytes = string.dump(print)
