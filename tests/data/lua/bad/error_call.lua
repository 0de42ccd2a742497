error("no lot given")
