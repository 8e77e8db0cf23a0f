# The tank in words, for a student who cannot see it (src/a11y/describe.rs).

describe-aligned-tight = tightly aligned
describe-aligned-loose = loosely aligned
describe-aligned-none = swimming every which way
describe-the-fish = The fish
describe-fish-count = { $count ->
        [one] { $count } fish
       *[other] { $count } fish
    }
describe-empty = The tank is empty.
describe-one-school = in one school
describe-alone = alone
describe-scattered = scattered ({ $groups } separate groups)
describe-in-groups = in { $groups } groups
describe-school = { $fish } { $arrangement }, { $alignment } (polarization { $polarization }), about { $spacing } body lengths apart, swimming at { $speed } metres per second
describe-milling = circling round their centre (milling { $milling })
describe-caught-so-far = Sharks have caught { $count ->
        [one] { $count } fish
       *[other] { $count } fish
    } so far.
describe-reef = The reef: { $predators ->
        [one] { $predators } predator
       *[other] { $predators } predators
    }, { $prey ->
        [one] { $prey } prey fish
       *[other] { $prey } prey fish
    }, { $pacifists ->
        [one] { $pacifists } pacifist
       *[other] { $pacifists } pacifists
    } and { $food ->
        [one] { $food } bit
       *[other] { $food } bits
    } of plankton.
describe-drill = Training drill { $drill } of { $drills }: { $percent } % done, best score { $best }.
describe-lab = The learning lab: { $learned } of { $drills } drills learned; the fish swims with { $source ->
        [shipped] the shipped
        [trained] its newly trained
       *[loaded] loaded
    } controllers.
describe-race = A race of { $count } fish is on.
describe-sharks-hunting = { $count ->
        [one] { $count } shark is
       *[other] { $count } sharks are
    } hunting.
describe-physics-fish = Fish { $number } swims at { $speed } metres per second.
describe-physics-fish-turning = Fish { $number } swims at { $speed } metres per second, turning.
describe-left-tank = Left tank: { $words }
describe-right-tank = Right tank: { $words }
describe-sees = The selected fish sees { $count ->
        [one] { $count } neighbour
       *[other] { $count } neighbours
    }.
describe-paused = Paused.
describe-selected = Selected: { $what }
describe-selected-body = Selected: fish { $number }, a { $species } { $length } metres long, swimming at { $speed } metres per second.
describe-selected-body-turning = Selected: fish { $number }, a { $species } { $length } metres long, swimming at { $speed } metres per second and turning.
describe-selected-sees = Selected: fish { $number }. It sees { $count ->
        [one] { $count } neighbour
       *[other] { $count } neighbours
    }.
describe-selected-sees-far = Selected: fish { $number }. It sees { $count ->
        [one] { $count } neighbour
       *[other] { $count } neighbours
    } and a school further off.
describe-fleeing = It is fleeing a shark.
describe-eaten = { $name } was eaten.
describe-mind = { $name } { $doing ->
        [avoid] is swerving round an obstacle
        [escape] is fleeing a predator
        [school] is schooling with others
        [eat] is hungry and going for food
        [mate] is courting
        [leave] is leaving the others
       *[other] is wandering
    } (hunger { $hunger }, fear { $fear }, libido { $libido }).
describe-trend = { $now }, { $direction ->
        [steady] steady
        [rising] rising
       *[falling] falling
    } (it was { $then } ten seconds ago)
describe-plots = Plots: polarization { $polarization }; nearest neighbour { $neighbour } body lengths; groups { $groups }; milling { $milling }; mean speed { $speed } metres per second.
describe-latest = Latest: { $events }.
describe-time = Time { $seconds } seconds, speed { $speed }×, seed { $seed }.
describe-split = The school split into { $groups } groups.
describe-together = The fish came together into one school.
describe-in-line = The fish now swim in line (polarization { $polarization }).
describe-out-of-line = The fish no longer swim in line (polarization { $polarization }).
describe-caught = { $count ->
        [one] A shark caught a fish
       *[other] Sharks caught { $count } fish
    } ({ $total } so far).
