# The schooling lab and the aquarium: the boids panel (src/ui/boids_panel.rs).

boids-tool-look = Look
    .help = Drag to turn the tank, scroll to zoom.
boids-tool-add-rock = Add rock
    .help = Click on the sand to put a rock there.
boids-tool-move-rock = Move rock
    .help = Drag a rock or pillar to a new place.
boids-tool-remove = Remove
    .help = Click a rock, pillar or ledge to take it out.
boids-compare = Compare two tanks
    .help = Show two tanks side by side with the same fish at the same start. Give them different urges and see how differently they behave.
boids-show-vision = Show vision
    .help = Draw what each fish can see: its field of view and lines to the neighbours it notices
boids-edit = Edit:
    .help = Choose which tank the controls below change
boids-rocks = Rocks
    .help = Change the rocks in the tank with the mouse
boids-rock-tools = rock tools
boids-restore-rocks = Restore the seed's rocks
    .help = Undo all rock changes in this tank
boids-preset-mystery = ? (mystery)
boids-rock-add-middle = Add a rock in the middle
    .help = Without a mouse: a new rock on the sand in the middle of the tank
boids-rock-no-room = There is no free place for another rock.
boids-no-rocks = No rocks in this tank.
boids-rock-previous = Previous rock
boids-rock-next = Next rock
boids-rock-where = Rock { $number } of { $count }: { $left } m from the left, { $front } m from the front
boids-rock-left = Left
    .name = Move the rock left
boids-rock-right = Right
    .name = Move the rock right
boids-rock-back = Back
    .name = Move the rock back
boids-rock-front = Front
    .name = Move the rock front
boids-rock-move-help = Move this rock { $step } m
boids-rock-remove-this = Remove this rock
boids-rock-cannot-go = That rock cannot go there: { $reason }
boids-tank-left = Left tank
boids-tank-right = Right tank
boids-tank-top = Top tank
boids-tank-bottom = Bottom tank

# The metrics plots under the tank (src/ui/metrics_panel.rs).

metrics-polarization = Polarization
    .help = How much the fish all swim the same way: the length of the average of their headings. High (near 1): every fish points the same way, like soldiers marching. Low (near 0): they point every which way, or go round in a circle (then milling is high).
metrics-milling = Milling
    .help = How much the schools swim round and round their own centre, like a whirlpool. High (near 1): a ring of fish circling a hole in the middle. Low (near 0): schools swimming straight, or loners. Only a group of at least 5 fish that keep within 1.5 body lengths of each other counts, and only the part of its turning beyond what random headings would give, so scattered loners read 0.
metrics-nearest = Nearest neighbour (body lengths)
    .short = Nearest neighbour
    .help = How far, on average, each fish is from its closest neighbour, measured in fish lengths. Low (about 1): the fish swim packed close, as a school keeps about one body length. High (2 or more): the fish are spread out through the tank.
metrics-groups = Groups
    .help = How many separate groups there are: fish closer than two body lengths belong together, so a loner is a group of one. 1: every fish is in one school. High (tens): the fish swim alone or in small bunches.
metrics-speed = Mean speed (m/s)
    .short = Mean speed
    .help = How fast the fish swim on average, in metres per second. High: the fish dart about; low: they cruise slowly (a tight school often swims slower than loners, because each fish brakes to keep its place).
metrics-line-solid = solid
metrics-line-dashed = dashed
metrics-line-dotted = dotted
metrics-tank-line = { $label } ({ $line } line)
metrics-urge-contain = contain
metrics-urge-align = align
metrics-urge-cohere = cohere
metrics-urge-separate = separate
metrics-urge-avoid = avoid
metrics-urges = Urges used (% of moves)
    .short = Urges used
    .help = How often each urge was used over the last second: containment, alignment, cohesion, separation, avoidance. In Blended mode every urge acts in every move (100 % each, mixed by its weight); in the one-urge modes the shares follow the weights. With two tanks, the upper bar of each pair is the left (or top) tank's, the lower the other's.
metrics-percent = { $value } %

# What the selected fish pays attention to (src/ui/boids_attention.rs).

boids-urge-containment = Containment
    .help = containment (stay in the tank)
boids-urge-alignment = Alignment
    .help = alignment (swim like the neighbours)
boids-urge-cohesion = Cohesion
    .help = cohesion (move to the neighbours' centre)
boids-urge-separation = Separation
    .help = separation (keep space)
boids-urge-avoidance = Avoidance
    .help = avoidance (swerve round obstacles)
boids-result-arrow = result
boids-rule-none = none
boids-rule-blended = Blended: every urge with a weight pulls at once, each by its weight's share (the arrows add up to the result).
boids-rule-classic = Classic: only the most pressing urge acts (its weight × how much it is needed now). This step: { $chosen }.
boids-rule-direct-alternate = Direct alternate: one dice roll, and every urge whose weight beats it acts at full strength. This step: { $chosen }.
boids-rule-monte-carlo = Monte Carlo: one urge is drawn by lottery; bigger weights hold more tickets. This step: { $chosen }.
boids-leader-alone = No fish leads: fish { $fish } sees no other fish right now, so only the tank, the rocks and its own wandering steer it.
boids-leader-neighbours = { $count ->
    [one] No fish leads: fish { $fish } reacts only to the { $count } neighbour it sees, and each of them to its own neighbours. The school's shape comes from all these small reactions together.
   *[other] No fish leads: fish { $fish } reacts only to the { $count } neighbours it sees, and each of them to its own neighbours. The school's shape comes from all these small reactions together.
}
boids-attention-title = What fish { $fish } pays attention to
boids-attention-title-tank = What fish { $fish } pays attention to ({ $tank })
boids-let-go = Let go
    .help = Stop showing this fish (or click open water)
boids-attention-not-yet = Press Play or Step: the fish has not swum since the settings changed, so there is nothing to show yet.
boids-attention-key = Arrows from the fish (ringed yellow): each urge, longer when stronger; solid when used this step, dashed when not; white is the result. White rings: the neighbours it heeds.
boids-urge = Urge
boids-strength = Strength
    .help = How hard the urge pulls, as the control mode weighs it: the acceleration it asks for, in metres per second per second
boids-used = Used?
boids-used-yes = yes
boids-used-always = always
boids-mystery = ?
    .help = A mystery value: your teacher hid it
boids-wander = Wander
    .help = Its own roaming: acts on top of every control mode
boids-fleeing = Fleeing a shark
    .help = It saw a shark (or felt its bow wave, or saw a neighbour flee) and swims away from it, on top of every control mode. While it flees, its cohesion weight counts double and its separation weight half: a frightened school bunches up.
boids-fear-weights = While it flees, a fright changes two of its weights: cohesion { $cohesion } (×{ $cohesion_factor }) and separation { $separation } (×{ $separation_factor }), so a frightened school bunches up.
boids-fear-weights-hidden = While it flees, a fright changes two of its weights: cohesion ×{ $cohesion_factor } and separation ×{ $separation_factor }, so a frightened school bunches up.
boids-result = Result
    .help = The steering the fish got this step (white arrow)
boids-speed-after = Speed
    .help = Its speed after the step
boids-heeds-none = It heeds no neighbour: it sees no other fish.
boids-heeds = { $count ->
    [one] It heeds { $count } neighbour (ringed): fish { $fish }.
   *[other] It heeds { $count } neighbours (ringed): fish { $fish }.
}
boids-far-school = It also sees a distant group of fish and is drawn a little towards it.
boids-leader = Is there a leader?

# The physical fish's controls and plots (src/ui/physics_panel.rs).

physics-title = Physical fish
physics-behaviour = The fish…
    .block = how they swim
physics-show-body = Show masses and springs
    .help = Draw each fish's skeleton: white dots are the 23 masses, lines the springs. The 12 muscles glow red when they pull and pale blue when they rest
physics-show-forces = Show forces
    .help = Yellow: the water pushing on the body (the push on the beating tail drives the fish forward). Green: where the fish wants to go. White: where it goes. Blue: the current
physics-selected-fish = Selected fish
    .help = Click a fish in the tank to select it: then you can steer it by hand, follow it with the camera and watch its muscles.
physics-selected-a-fish = Selected: fish { $index }
physics-selected-a-shark = Selected: shark { $index }
physics-deselect = Deselect
    .help = Let go of this fish
physics-follow = Camera follows it
    .help = Keep this fish in the middle of the view as it swims
physics-hand = Steer it by hand
    .help = You give the orders: how fast its tail beats and when it turns. The other fish keep steering themselves
physics-turn-left = Turn left
physics-turn-right = Turn right
physics-turn-help = Contract the muscles on one side quickly, then let them go slowly: the fish bends and swims round
physics-side-left = left
physics-side-right = right
physics-plots-hint = Click a fish to see its twelve muscles at work and how fast it swims.
physics-muscles-front = Front muscles (turning)
physics-muscles-middle = Middle muscles (turning and swimming)
physics-muscles-tail = Tail muscles (swimming)
physics-muscles = Muscles
    .help = How hard each muscle of this part pulls, from 0 (resting) to 1 (fully contracted), over the last seconds. Solid vermillion lines: the fish's left side; dashed blue lines: its right side (two muscles each, the top one thicker than the bottom one). Left and right take turns: that is the tail beat. High, tall waves: the fish beats its tail hard to swim fast; flat near 0: it glides; one side high for a moment while the other rests: it turns.
physics-muscle-top = { $side } top
physics-muscle-bottom = { $side } bottom
physics-speed = Speed (m/s)
    .help = How fast the fish's middle moves, in metres per second. High: it swims hard, tail beating; low or near 0: it glides or hovers. A wobble that rises and falls with each tail beat is normal.
physics-speed-line = speed

# The panels under the tank (src/ui/bottom_panel.rs).

metrics-bottom-panel =
    .name = Plots and readings

# The status line under the tank (src/ui/status_line.rs).

status-fps = { $fps } FPS
    .help = Pictures drawn per second
status-steps = { $steps } steps/s
    .help = Simulation steps computed per second of real time
status-tank-pixels = , tank at { $percent } % of the pixels
status-graphics =
    .help = The graphics system your browser gave Shoal: WebGPU is the newest, WebGL2 works everywhere else. "tank at N % of the pixels": the graphics cannot keep up, so the tank is drawn with fewer pixels to stay smooth (View › Tank detail)
status-time = t = { $seconds } s
    .help = Simulated time since the start
status-fish-mystery = ? fish
    .help = Your teacher hid the number of fish: count them, or work it out from what they do
status-paused = paused
status-slowed = slowed down
    .help = This computer cannot keep up with the chosen speed, so the simulation runs slower than asked (nothing is skipped: the fish just move in slow motion). Try fewer fish or a lower speed.

## What the physics fish do (src/sim/physics/world.rs).
physics-behaviour-school = School
    .explanation = The fish steer with the schooling urges and their muscles follow.
physics-behaviour-wander = Wander
    .explanation = Each fish explores on its own.
physics-behaviour-drift = Drift
    .explanation = The muscles rest: the fish glide to a stop and the current carries them.

# What each control mode does, under the mode's name (ControlMode::explanation).
boids-mode-blended-explanation = Every urge pulls a little, all at once, mixed by its weight.
boids-mode-classic-explanation = Each moment the fish follows only its most pressing urge.
boids-mode-direct-alternate-explanation = Each moment every urge gets a dice roll; urges with big weights win the roll more often.
boids-mode-monte-carlo-explanation = Each moment the fish picks one urge by lottery; bigger weights get more tickets.
