# The reef: its animals, its event log (src/sim/reef/) and its panels (src/ui/reef_*.rs).

reef-animal = { $kind ->
    [shark] shark { $index }
    [fish] fish { $index }
   *[pacifist] pacifist { $index }
}

## The event log (src/sim/reef/events.rs and the stages that log).

event-fled = { $fish } fled from { $predator }
event-ate = { $predator } ate { $prey }
event-ate-plankton = { $fish } ate plankton (hunger { $before } → { $after })
event-missed = { $predator } missed { $prey }: { $crowd } other prey around it confused it
event-chose = { $female } chose { $male } ({ $male_length } m long) over { $over } ({ $over_length } m): { $why ->
    [bigger] she prefers bigger males
   *[nearer] she weighs size against distance, and the bigger one was farther away
}
event-left-for-larger = { $female } left { $old } for the larger { $new }
event-began-courting = { $male } and { $female } began courting: looping
event-courtship-phase = { $male } and { $female } began { $phase ->
    [circling] circling
    [ascending] spawning ascent
    [nuzzling] nuzzling
    [spawned] spawned
   *[looping] looping
}
event-spawned = { $male } and { $female } spawned
event-stopped-courting = { $male } and { $female } stopped courting
event-school-split = The school split into { $groups } groups
event-school-split-at-pillar = The school split into { $groups } groups at the pillar
event-school-joined = The school joined up again
event-school-at-pillar = The school reached the pillar
event-school-passed-whole = The whole school went by on one side of the pillar
