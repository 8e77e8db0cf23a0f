# *About this scene* (src/ui/about.rs, src/ui/about_text.rs), the share QR
# code's refusal (src/ui/qr.rs) and the desktop window's title (src/main.rs).

about-app-title = Shoal — a virtual ethology lab
about-button = ℹ About this scene
    .help = What this scene shows, how it works, what to notice and what to try
about-window-title = About: { $scene }
about-how = How it works
about-notice = Things to notice
about-try = Things to try
about-equations = The equations
about-equations-docs = Every constant, its source and where Shoal departs from the papers: the docs/ folder of the project.
about-references = References
about-qr-too-long = the link is too long for a QR code ({ $count ->
        [one] { $count } character
       *[other] { $count } characters
    }): shorten the question or remove some rules

# References (shown under *References*).
about-ref-tu-terzopoulos = Tu, X. & Terzopoulos, D. (1994). Artificial fishes: physics, locomotion, perception, behavior. Proceedings of SIGGRAPH 94, 43–50; and Artificial Life 1(4), 327–351.
about-ref-lim-tan = Lim, L. & Tan, K. Virtual ethology: simulation of aquatic animal heterogeneous behaviours as particle-based autonomous agents (SIMBA); and (2018) Understanding steering mechanisms for simulating fish behaviours. JISTM 3(8).
about-ref-reynolds = Reynolds, C. W. (1987). Flocks, herds and schools: a distributed behavioral model. Computer Graphics 21(4), 25–34.
about-ref-couzin = Couzin, I. D., Krause, J., James, R., Ruxton, G. D. & Franks, N. R. (2002). Collective memory and spatial sorting in animal groups. Journal of Theoretical Biology 218, 1–11.
about-ref-ballerini = Ballerini, M. et al. (2008). Interaction ruling animal collective behavior depends on topological rather than metric distance. PNAS 105(4), 1232–1237.
about-ref-pitcher = Pitcher, T. J. & Partridge, B. L. (1979). Fish school density and volume. Marine Biology 54, 383–394.
about-ref-landeau = Landeau, L. & Terborgh, J. (1986). Oddity and the 'confusion effect' in predation. Animal Behaviour 34, 1372–1380.
about-ref-videler = Videler, J. J. (1993). Fish Swimming. Chapman & Hall.
about-ref-kirkpatrick = Kirkpatrick, S., Gelatt, C. D. & Vecchi, M. P. (1983). Optimization by simulated annealing. Science 220, 671–680.

# The equations: each message is the name, its .formula the formula and what its letters mean.
about-eq-seek = Seek a wished velocity
    .formula = steering = v_wish − v, then limited to the largest steering force (8 m/s² by default); v is the fish's velocity. Speeds are capped at the top speed.
about-eq-wander = Wander
    .formula = wish = towards a point on a circle ahead of the fish; the point's angle on the circle drifts a little at random each step, so the path meanders.
about-eq-containment = Containment and avoidance
    .formula = look ahead along the path; if it would come within 1 m of the glass, sand or surface, or hit a rock, steer along the obstacle instead of into it.
about-eq-alignment = Alignment
    .formula = wish = the mean heading of the (up to 7) nearest neighbours it sees, nearer ones counting more, times the top speed.
about-eq-cohesion = Cohesion
    .formula = wish = towards the centre of those neighbours (and of the distant school it sees).
about-eq-separation = Separation
    .formula = wish = away from each neighbour closer than the personal space (0.8 m), stronger the closer it is.
about-eq-weights = Weights
    .formula = each urge's slider w (0–100) scales it: a full containment, alignment, cohesion or separation slider gives 25 % of the largest steering force, a full avoidance slider 100 %.
about-eq-blended = Blended (direct)
    .formula = acceleration = Σ wᵢ · urgeᵢ over the five urges, then limited.
about-eq-classic = Classic
    .formula = one urge per step: the one with the largest wᵢ × |urgeᵢ| acts alone, at its full share.
about-eq-direct-alternate = Direct alternate
    .formula = draw ρ in [0, 1]; every urge with weight wᵢ ≥ ρ (weights as shares of 100) acts.
about-eq-monte-carlo = Monte Carlo
    .formula = draw ρ in [0, Σw); the one urge whose slice of 0…Σw holds ρ acts (so it is chosen with probability wᵢ / Σw).
about-eq-polarization = Polarization
    .formula = p = |Σ v̂ᵢ| / N, the length of the mean heading: 1 when every fish swims the same way, near 0 when they point every which way.
about-eq-milling = Milling
    .formula = m = |Σ r̂ᵢ × v̂ᵢ| / N about each group's centre (r̂ᵢ points from the centre to fish i): 1 when the fish circle round their centre like a doughnut. A group counts only with at least 5 fish within 1.5 body lengths of each other, and only its turning beyond chance: (m − 1/√k) / (1 − 1/√k) for a group of k fish.
about-eq-nearest = Nearest neighbour and groups
    .formula = NND = the mean distance to each fish's nearest neighbour, in body lengths; a group is fish linked by gaps of at most two body lengths.
about-eq-springs = Springs
    .formula = f = c · (|r| − l) · r / |r|: a spring of stiffness c and rest length l pulls its two masses together when stretched and pushes them apart when squeezed (r runs from one mass to the other). c = 38 for cross springs, 28 for muscles, 30 for the rest.
about-eq-mass-motion = Motion of each mass
    .formula = m ẍ + γ ẋ = Σ spring forces + water force, with masses m from 0.165 to 11 and damping γ = 0.05; solved implicitly (each step solves for the new velocities together), so stiff springs cannot blow up.
about-eq-muscles = Muscles
    .formula = a muscle contracts by shortening its rest length: rest = l − u · (l − l_min), with u in [0, 1] set by the motor controller and l_min its fully contracted length.
about-eq-water = Water
    .formula = on each small triangle of skin, f = −A (n · v) n when the triangle moves into the water (A its area, n its outward normal, v its velocity through the water); nothing when it moves away. A tail that beats sideways is pushed forward.
about-eq-fins = Fins
    .formula = F = −A |v| cos θ · n: tilting the pectoral fins up lifts, down dives; held square to the flow they brake.
about-eq-hunger = Hunger
    .formula = H = min(1 − n · (1 − p₀ Δt_H) / α, 1): n food eaten at the last meal, Δt_H time since then (in paper time units of 1/40 s), p₀ how fast food digests, α appetite.
about-eq-libido = Libido
    .formula = L = min(p₁ Δt_L · (1 − H), 1): Δt_L time since mating; a hungry fish has little libido.
about-eq-fear = Fear
    .formula = F = min(Σᵢ min(D₀ / dᵢ, 1), 1) over the predators it sees, dᵢ their distances.
about-eq-intention = The intention generator
    .formula = in order: something in its way → avoid; F > f₀ → school (if it schools and the worst fear is below f₁) or escape; max(H, L) > r → eat or mate, whichever is larger; water it dislikes → leave; else wander.
about-eq-shark-choice = The shark's choice
    .formula = it hunts the prey k with the smallest C = d · (1 + 0.5 S + 0.2 E / π): d the distance, S = 1 if that prey swims in a school, E the turn it would need. A school costs more.
about-eq-her-choice = Her choice
    .formula = a female ranks the males she sees by 0.2 d − 10 L (d distance, L his length in metres; lower wins): 10 cm longer is worth 5 m nearer.
about-eq-objective = What it tries to improve
    .formula = E = ∫ (μ₁ E_u + μ₂ E_v) dt: E_v measures how far it is from the drill's goal (the distance left, or the difference from the speed or turn asked), E_u = ½(ν₁ |u̇|² + ν₂ |ü|²) punishes jerky muscle moves. Lower is better.
about-eq-muscle-controls = The muscle controls
    .formula = each of the 12 muscles' contraction u(t) is given at 15 moments and joined by a smooth curve (a spline).
about-eq-annealing = Simulated annealing
    .formula = change the 15 × 12 numbers a little at random; keep the change if E is lower; keep a worse one with probability e^(−ΔE / T), where the temperature T falls over the tries, so early on it explores and later it only improves.
about-eq-abstraction = Abstraction
    .formula = a Fourier transform finds the main rhythms of the learned moves; keeping only them gives a simple controller, and interpolating between drills gives a speed and steering map.

# aquarium
about-aquarium-what = An aquarium of fish that wander. Each fish is a point with a speed and a heading, drawn as a fish. Nothing tells them to school.
about-aquarium-how = Every 1/60 of a second each fish picks a wished direction: a little wander (a point on a circle ahead of it that drifts at random), plus turning away from the glass, the sand and the surface, and round rocks and pillars. It steers towards the wish as hard as its turning power allows, never faster than its top speed.
about-aquarium-notice-1 = Fish turn before they reach the glass: they look ahead along their path.
about-aquarium-notice-2 = They swerve round a pillar instead of stopping at it.
about-aquarium-notice-3 = Two fish meeting do not line up: they have no urge to follow each other.
about-aquarium-try-1 = Set Fish to 2,000 and look from above (drag the view).
about-aquarium-try-2 = Open the Schooling lab and compare: what do its fish do that these do not?

# schooling
about-schooling-what = A virtual ethology lab: fish that follow five urges, as in Lim & Tan's SIMBA. Change the urges and watch a school form, or fall apart. Compare two tanks that differ only in the urges.
about-schooling-how = Each fish sees its neighbours (5 m, all round except a blind cone behind) and heeds the 7 nearest it sees. Five urges each wish a velocity: stay in the tank (containment), swim like the neighbours (alignment), stay close (cohesion), keep some space (separation) and dodge rocks and other fish (avoidance). The sliders weigh them, and the control mode says how they combine: all together, or one at a time. There is no leader: every fish follows the same rules and only reacts to the few neighbours it sees.
about-schooling-notice-1 = The Group preset makes a school: polarization near 0.8, one group, neighbours about a body length apart. Individual leaves them scattered.
about-schooling-notice-2 = A school turns as one, yet no fish decides where it goes.
about-schooling-notice-3 = With a shark, fish in a school are caught less often: the shark is confused by many fish around its target.
about-schooling-try-1 = Turn alignment to 0 in the Group tank. What happens to polarization?
about-schooling-try-2 = Compare two tanks: does the school or the loners lose fewer fish to a shark?
about-schooling-try-3 = Switch the control mode to Monte Carlo and read the urge bars.
about-schooling-try-4 = Add a rock in the school's path and watch it split and join.

# physics
about-physics-what = Fish with bodies: 23 masses joined by 91 springs, 12 of them muscles, as in Tu & Terzopoulos. Nothing pushes the fish forward but the water on its beating tail.
about-physics-how = Muscles shorten and lengthen in turn on the two sides, bending the body left and right. Each patch of skin that moves into the water is pushed back by it; a tail swept sideways gets a push that is partly forwards, so the fish swims. A motor controller turns a wished speed into how far and how fast the muscles pull, another turns a wished turn into a bend, and the pectoral fins climb, dive and brake. The same urges as the schooling lab give each fish its wish.
about-physics-notice-1 = Select a fish and read its twelve muscles: the two sides pull in turn.
about-physics-notice-2 = Show forces: the yellow push of the water is largest on the tail.
about-physics-notice-3 = A fish cannot stop dead or turn on the spot: it has a body to move.
about-physics-try-1 = Steer a fish by hand: how does its speed change with the swim speed slider?
about-physics-try-2 = Turn on the current and watch a fish that stops swimming drift.
about-physics-try-3 = Turn left by 30° and by 90°: which takes longer?

# reef
about-reef-what = A reef of fish with minds, as in Tu & Terzopoulos: they see, get hungry, get scared and court. Each decides what to do from what it sees and how it feels. Click a fish to look inside its head.
about-reef-how = Each fish sees all round except behind, as far as the water is clear, and not through rocks or other fish. Hunger grows as its food digests, libido with time since mating, fear with predators close by. An intention generator picks one intention in a fixed order (avoid, escape or school, eat or mate, leave, wander), remembers an interrupted one, and a behaviour routine drives the body's motor controllers: swim, turn, fins.
about-reef-notice-1 = A frightened school flees together; a shark striking into a crowd often misses.
about-reef-notice-2 = Courting females choose the bigger male (the log says so).
about-reef-notice-3 = A fish that swerves round a rock goes back to the food it was after: it remembers.
about-reef-try-1 = Open Predator and school and Skip to the moment: watch the shark's catch.
about-reef-try-2 = In Minds, make the prey timid or courageous and count the catches.
about-reef-try-3 = Make the water murky (Visibility): do fish find less food?

# learning
about-learning-what = How a fish learns to swim, as in Tu & Terzopoulos: starting from random muscle moves, it keeps what works. Then it races copies of itself that practised less.
about-learning-how = A drill sets a goal (swim far, swim at a speed, turn). The fish tries a pattern of muscle moves, measures how well it did, changes the pattern a little and keeps the change if it did better (and, early on, sometimes even if it did worse, so it does not get stuck). Over thousands of tries it finds a rhythm like a real fish's tail beat.
about-learning-notice-1 = The objective falls quickly at first, then slowly.
about-learning-notice-2 = The learned moves are rhythmic: two or three main rhythms explain them.
about-learning-notice-3 = Practice helps a lot at first and then levels off: in the race, the copies that practised a few thousand tries swim about equally fast.
about-learning-try-1 = Train with 90 tries per drill, then with 6,840: compare the race.
about-learning-try-2 = Switch the swimmer between learned and hand-tuned controllers.
about-odd = Model description (ODD)
    .help = The model described the way ecologists describe agent-based models (the ODD protocol, Grimm et al. 2020): purpose, entities, scales, schedule, design concepts, initialisation, input and submodels. Opens in a new tab.
