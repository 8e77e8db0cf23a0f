# The confusion effect and joint flight switches (schooling lab and reef).
predation-heading = Our additions to the papers
    .help = Two ways a school protects its fish that neither paper (Reynolds 1987, Tu & Terzopoulos 1994) has. We added them; switch them off to see what the papers' fish do without them.
predation-confusion = Confusion effect
    .help = A predator is confused by the many fish around the one it chases. Schooling lab: a shark loses its lock on its target, more often the more fish swim close to it. Reef: a strike misses more often the more prey swim near its target. Off: every attack goes on as if the target were alone.
predation-joint-flight = Joint flight
    .help = A frightened school flees together. Schooling lab: a fish that sees a neighbour flee gets frightened too, so the alarm runs through the school. Reef: a schooling fish flees with the schoolmates it sees. Off: each fish flees only from a predator it notices itself, on its own.
predation-paper-only = Paper only: both off
    .help = Switches off the confusion effect and joint flight, and nothing else.
