# The reef: its animals, its event log (src/sim/reef/) and its panels (src/ui/reef_*.rs).

reef-animal = { $kind ->
    [shark] shark { $index }
    [fish] fish { $index }
   *[pacifist] pacifist { $index }
}

## The event log (src/sim/reef/events.rs and the stages that log).

reef-event-fled = { $fish } fled from { $predator }
reef-event-ate = { $predator } ate { $prey }
reef-event-ate-plankton = { $fish } ate plankton (hunger { $before } → { $after })
reef-event-missed = { $predator } missed { $prey }: { $crowd } other prey around it confused it
reef-event-chose = { $female } chose { $male } ({ $male_length } m long) over { $over } ({ $over_length } m): { $why ->
    [bigger] she prefers bigger males
   *[nearer] she weighs size against distance, and the bigger one was farther away
}
reef-event-left-for-larger = { $female } left { $old } for the larger { $new }
reef-event-began-courting = { $male } and { $female } began courting: looping
reef-event-courtship-phase = { $male } and { $female } began { $phase ->
    [circling] circling
    [ascending] spawning ascent
    [nuzzling] nuzzling
    [spawned] spawned
   *[looping] looping
}
reef-event-spawned = { $male } and { $female } spawned
reef-event-stopped-courting = { $male } and { $female } stopped courting
reef-event-school-split = The school split into { $groups } groups
reef-event-school-split-at-pillar = The school split into { $groups } groups at the pillar
reef-event-school-joined = The school joined up again
reef-event-school-at-pillar = The school reached the pillar
reef-event-school-passed-whole = The whole school went by on one side of the pillar

## The reef's panel (src/ui/reef_panel.rs).

reef-intention-avoid = something is in its way: it swerves
    .word = avoid
reef-intention-escape = a predator is close: it flees
    .word = escape
reef-intention-school = it swims with the others of its kind
    .word = school
reef-intention-eat = it is hungry: it looks for food
    .word = eat
reef-intention-mate = it wants to mate: it courts
    .word = mate
reef-intention-leave = it does not like the water here: it leaves
    .word = leave
reef-intention-wander = all is well: it wanders
    .word = wander
reef-heading = Reef
reef-body = Body
    .help = Muscles: each fish is a body of springs that swims by bending (slower to compute, true to the paper). Points: each fish is a dot that steers directly (fast, for big scenes). The mind is the same.
reef-body-muscles = Muscles
reef-body-points = Points
reef-show-water = Show water
    .help = Colour the water by how bright or how warm it is. Some fish like light or warmth and leave water they do not like
reef-show-vision = Show what the selected fish sees
    .help = A fish sees all around except a narrow blind cone behind, as far as the water is clear. The coloured line points at what it is thinking about
reef-name-tags = Name tags
    .help = Write each animal's name over it, as the event log calls it ("shark 10", "fish 5"): click a line of the log to follow that fish
reef-follow = Camera follows it
    .help = Keep the selected fish in the middle of the view
reef-deselect = Deselect
    .help = Let go of the fish
reef-animal-number = animal { $index }
reef-selected = Selected: { $name } (its mind is shown below)
reef-select-hint = Click a fish in the tank to look inside its head.

## The demos (src/sim/reef/demos.rs): name, one sentence, and the moment *Skip* looks for.

reef-demo-reef = Reef
    .help = A whole reef: fish feed on plankton, a shark hunts a school, pairs court.
    .moment = the next catch or spawning
reef-demo-predator-and-school = Predator and school
    .help = A hungry shark and a school of prey: who gets caught?
    .moment = the shark's next catch
reef-demo-courtship = Courtship
    .help = Two males court one female; she prefers the bigger one.
    .moment = the spawning
reef-demo-feeding = Feeding
    .help = Hungry fish find plankton and suck it in.
    .moment = the next bite
reef-demo-school-meets-obstacle = School meets obstacle
    .help = A school meets a pillar: does it split around it and join up again?
    .moment = what the school does next

## Skip to the moment (src/ui/reef_skip.rs); $time is simulated time as "1:05".

reef-skip = Skip to { $what } »
    .help = Run ahead as fast as this computer can until it happens, then go back a few seconds so you can watch it. The run is the same one: skipping only changes when you see it
reef-skip-looked = looked { $time } ahead
reef-skip-cancel = Cancel
reef-skip-banner = Looking ahead for { $what }… { $time }
reef-skip-found = Skipped ahead to { $time }. Watch: in about { $seconds } s the log will say “{ $line }”.
reef-skip-not-found = No sign of { $what } in the next { $time } of this run: it carries on from there. Try another seed.

## Minds (src/ui/reef_minds.rs).

reef-minds = Minds
    .help = How fast each kind of fish gets hungry or wants to mate, how far away a shark frightens it, and its character. Changes apply at once.
reef-minds-sharks = Sharks
    .help = The hunters: they eat prey fish
reef-minds-prey = Prey fish
    .help = Small fish that school and flee the shark
reef-minds-pacifists = Pacifists
    .help = Fish that graze on plankton and court
reef-minds-none-here = None of these in this demo
reef-minds-no-fish = No fish in this reef.
reef-minds-reset = The demo's own values
    .help = Undo every change to this kind of fish

## Drawn over the tank (src/ui/reef_overlay.rs).

reef-her-choice = her choice

## The inspector under the tank (src/ui/reef_inspector.rs).

reef-tab-mind = Mind
reef-tab-history = Last 2 min
reef-tab-sees = Sees
reef-tab-log = Events
reef-summary = { $animals } animals alive · { $plankton } plankton · { $eaten } prey eaten · { $spawnings } spawnings
reef-summary-hint = Click a fish to see its hunger, fear and plans, and what it sees.
reef-sees = What it sees
    .help = The world through this fish's eye: it sees almost all around, squeezed into a circle. Its brain only uses how bright it is
reef-brightness = Brightness { $value }
reef-water = Water { $value } °C
# $sex: male, female; $kind: predator, prey, pacifist.
reef-inspector-title = { $name } · { $sex ->
    [male] male
   *[female] female
} { $kind ->
    [predator] predator
    [prey] prey
   *[pacifist] pacifist
}
reef-inspector-eaten = { $name } · eaten
# $light: bright, dim, any; $temperature: warm, cool, any; $schools: yes, no.
reef-inspector-habits = Species { $species } · { $length } m · likes { $light ->
    [bright] bright
    [dim] dim
   *[any] any
} light, { $temperature ->
    [warm] warm
    [cool] cool
   *[any] any
} water{ $schools ->
    [yes] {" · schools"}
   *[no] {""}
}
    .help = Habits: what this fish was born liking. They never change.
reef-inspector-hunger = Hunger
    .help = Grows as food digests; drops when it eats. Near 1: the fish is very hungry and will go looking for food; near 0: it has just eaten.
    .plot = hunger
reef-inspector-libido = Libido
    .help = Grows with time since mating, unless it is hungry. Near 1: it looks for a partner and courts; near 0: it has just spawned (or is too hungry to care).
    .plot = libido
reef-inspector-fear = Fear
    .help = High when it sees a predator close by. Near 1: a shark is near and the fish flees (or hides in its school); near 0: no predator in sight.
    .plot = fear
reef-intention-hunt = it is hungry: it hunts
reef-inspector-intends = Intends to { $intention }: { $sentence }
reef-inspector-focus = Focus: { $target }
reef-inspector-remembers = Remembers: { $intention } { $target } (resumes it after swerving)
reef-inspector-remembers-nothing = Remembers: nothing
reef-inspector-courting = Courting: { $phase ->
    [circling] circling
    [ascending] spawning ascent
    [nuzzling] nuzzling
    [spawned] spawned
   *[looping] looping
} with { $partner } ({ $count })
# $fins: degrees with their sign ("+12").
reef-inspector-muscles = Muscles: swim { $speed } %{ $turning ->
    [yes] {", turning"}
   *[no] {""}
}, fins { $fins }°
    .help = What the brain tells the muscles this moment
reef-inspector-speed = Speed { $speed } m/s (point body)
reef-target-nothing = nothing in particular
reef-target-plankton = plankton { $id }
reef-target-rock = rock { $id }
reef-target-glass = the glass
reef-inspector-history = Its mind over the last two minutes
reef-log = What happened
    .help = Newest first: meals, chases, courtship. Click a line to follow who did it
reef-log-empty = Nothing yet.
reef-log-follow = Click to select and follow { $who }
