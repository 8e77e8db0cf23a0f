# The guided investigations (src/investigation/, src/ui/investigation_panel.rs,
# src/ui/investigation_plot.rs): the five investigations' words, the runs'
# results, the window and the student's record.

## The curve shapes a student can sketch.

inv-shape-flat = Flat: it makes no difference
inv-shape-line = A straight line up
inv-shape-levels = Up fast, then levels off
inv-shape-peak = Up, then down again
inv-shape-down = Down

## Why do fish school?

inv-why-school = Why do fish school?
    .teaser = A shark hunts loners in one tank and a school in the other. Who loses fewer fish?
    .intro = Two tanks with the same 40 fish and one shark each. On the left the fish are loners (the Individual urges); on the right they school (the Group urges). Nothing else differs.
    .question = In 3 minutes, which tank will lose fewer fish to its shark?
    .choice-loners = The loners (Individual tank)
    .choice-school = The school (Group tank)
    .choice-same = About the same
    .run-hint = Run starts both tanks again from the same start and counts for 3 simulated minutes. Watch each shark: does it chase one fish to the end, or switch? Raise the Speed slider to get there sooner. The plot in this window counts each tank's catches.
    .prompt-1 = Look at the catches plot in this window. When did each shark catch its fish: steadily, or in bursts?
    .prompt-2 = Watch the shark near the school (the Group tank). What happens to the fish it was chasing?
    .prompt-3 = Why might it be harder to catch a fish in a crowd?
    .reveal = Many predators catch fewer prey in a school. Landeau and Terborgh (1986) let largemouth bass hunt silvery minnows: a lone minnow was caught at once, but against shoals of 8 or more the bass often failed, because it kept switching targets. This is the confusion effect. Our shark has it too: each second it loses its lock on its target at a rate that grows with the number of fish close to the target, and needs a second to pick another one, so a lone fish is never lost and a fish in a tight school almost at once. Schools also see a shark sooner (many eyes) and dilute the risk; our model has the confusion and fleeing, not the many eyes. One run is one chance: over seeds 1 to 10 of this setting (in the browser) the loners lost 78 fish and the schools 31; the school lost clearly fewer in 8 runs of the 10, as many in 1, and more in 1. Press New next to Seed and run again to see. Now switch the confusion off: in the side panel, under Our additions to the papers, untick Confusion effect, then press Reset and watch 3 minutes again. We measured it on 8 other seeds (41 to 48): with the confusion on, the loners lost 48 fish and the schools 24 (the school lost fewer in 7 tanks of 8); with it off, the loners lost 58 and the schools 55 (the school lost fewer in only 4 of 8). Without the confusion our school is no safer than the loners: a shark beside it always has a fish within reach. The confusion effect is our addition to the model; Reynolds and Tu and Terzopoulos do not have it.
    .reference = Landeau & Terborgh 1986, Anim. Behav. 34:1372; Lim & Tan, SIMBA (predator species); Shoal's shark: docs/boids.md

## Is there a leader?

inv-leader = Is there a leader?
    .teaser = A school turns as one. Does one fish lead it?
    .intro = One tank of 60 schooling fish (the Group urges). Watch the school turn together.
    .question = Does one fish lead the school?
    .choice-yes = Yes, one fish leads
    .choice-no = No, nobody leads
    .run-hint = Click fish (at least one) to see what each one heeds: the white rings are the neighbours it reacts to. Then turn alignment off and on with the buttons below and watch the polarization (1: all swim the same way).
    .prompt-1 = Which neighbours did the fish you clicked pay attention to? Was any of them special?
    .prompt-2 = What happened to the school when alignment was off?
    .prompt-3 = So how can a school turn together without a leader?
    .reveal = No fish leads. Each fish reacts only to the few neighbours it sees (here its 7 nearest, as starlings do: Ballerini et al. 2008), and the whole school's turn emerges from these local reactions. Thinking a flock or school must have a leader is a common misconception (Resnick 1996). Turning alignment off lets the fish keep together but point every way: the measured polarization shows it. Real schools do follow informed individuals sometimes (Couzin et al. 2005: a few fish that know where food is can steer a school without anyone recognising them), but no fish is in charge.
    .reference = Resnick 1996, Beyond the centralized mindset; Ballerini et al. 2008, PNAS 105:1232; Couzin et al. 2005, Nature 433:513

## Which urge makes a school?

inv-which-urge = Which urge makes a school?
    .teaser = Turn the alignment urge from 0 to 100: how does the school's order change?
    .intro = One tank of schooling fish. The alignment urge makes a fish swim the way its neighbours swim. The experiment runs the tank at six alignment weights, three times each with different seeds, and measures the polarization (0: every fish its own way, 1: all the same way).
    .question = How does the school's polarization change as alignment goes from 0 to 100? Choose the shape.
    .x-label = alignment weight
    .y-label = polarization
    .run-hint = The tank keeps swimming while the experiment runs its 18 runs in the background. Try the alignment slider yourself meanwhile.
    .prompt-1 = Where does your sketch differ most from the measured curve?
    .prompt-2 = Why does a little alignment already make such a difference (or not)?
    .prompt-3 = Is alignment alone enough to make a school? What would cohesion add?
    .reveal = In models of this kind (Vicsek et al. 1995; Couzin et al. 2002) order appears suddenly: below some strength of alignment the group is disordered, above it the fish line up, like a phase transition (a sudden change of state, as when water freezes into ice). Ours measures how polarization grows with the alignment weight with the other urges fixed at the Group preset's: the bar at each point is a 95 % interval: where the average of many more tanks would very likely fall, worked out from three tanks (three is few, so the bars are rough: about the range of the three). In our tank order comes quickly: from about 0.2 without alignment to about 0.7 at a weight of 20, levelling off near 0.9 from 40 on. The rise is less sharp than a textbook transition because the tank is small (60 fish) and its walls keep turning the school.
    .reference = Vicsek et al. 1995, Phys. Rev. Lett. 75:1226; Couzin et al. 2002, J. Theor. Biol. 218:1; Lim & Tan, SIMBA (the five urges)

## How does a fish swim?

inv-how-swim = How does a fish swim?
    .teaser = Beat the tail faster: does the fish swim faster, and without limit?
    .intro = A physics fish: 23 masses, 91 springs, 12 of them muscles. The muscles bend the body from side to side; the water pushes back on the tail and the fish moves forward. The experiment drives one body at full strength at seven tail-beat frequencies and measures its speed.
    .question = How does the fish's top speed change as its tail beats faster (1 to 5 beats a second)? Choose the shape.
    .x-label = tail beats per second (Hz)
    .y-label = speed (body lengths/s)
    .run-hint = The measurement swims a separate body at each beat, a little every frame. Meanwhile watch the selected fish's muscles glow red as they pull.
    .prompt-1 = How much farther does the fish go for each extra beat per second?
    .prompt-2 = What happened at the fastest beat? Look at the muscles and the tail.
    .prompt-3 = Why can't a fish go faster and faster just by beating faster?
    .reveal = Real fish swim faster the faster they beat their tail, close to a straight line over their cruising range, each beat carrying them about 0.6 to 0.7 body lengths (Bainbridge 1958; Webb's reviews); the tail beat cannot rise without limit because muscles contract only so fast. Tu and Terzopoulos' fish swims the same way, through its springs and a simple water force. Ours: speed grows about linearly up to 3 beats a second, each beat gaining only about 0.25 body lengths (our water has no added mass and the tail fin is small); above 3 beats a second each extra beat gains less, and at 5 the fish swims slower than at 4: the passive tail can no longer follow the beat, a limit of our spring model, not the muscle limit of real fish.
    .reference = Bainbridge 1958, J. Exp. Biol. 35:109; Webb 1975, Hydrodynamics and energetics of fish propulsion; Tu & Terzopoulos 1994 §3; Shoal: docs/fish-body.md

## Learning to swim

inv-learning = Learning to swim
    .teaser = A fish practises swimming. Does the one that practised longer swim farther?
    .intro = A shark that does not know how to swim tries random muscle moves and keeps the ones that take it farther (simulated annealing). Copies are saved after 90, 1440, 2790, 4140, 5490 and 6840 tries; then all six race.
    .question = Will the copy that practised longest (6840 tries) swim farthest?
    .choice-clearly = Yes, clearly farthest
    .choice-just = Yes, but only just
    .choice-no = No, practice stops helping
    .run-hint = The shark practises the first drill (swim as far as you can) a little every frame: the plot under the tank shows how well it swims. Then the six copies race.
    .prompt-1 = Which copies gained the most from their extra practice?
    .prompt-2 = Why might the last few thousand tries help so little?
    .reveal = Tu and Terzopoulos' shark trained for 6840 steps 'wins the race decisively'. Ours learns fast at first (the 90-try copy barely moves; the 1440-try copy is already close) and then hardly improves: the annealing has nearly converged by 4140 tries, so the last copies finish within about 1 % of each other, and the longest-trained one does not always win. Learning curves of people and animals have the same shape: large early gains, small late ones (the 'power law of practice', Newell & Rosenbloom 1981).
    .reference = Tu & Terzopoulos 1994 §4 and Fig. 7; Newell & Rosenbloom 1981; Shoal: docs/learning.md

## The runs' results (src/investigation/measure.rs, outcome.rs).

inv-verdict-agrees = You predicted "{ $prediction }". { $numbers } The measurement agrees with your prediction.
inv-verdict-instead = You predicted "{ $prediction }". { $numbers } The measurement points to "{ $supported }" instead.
inv-curve-verdict-closest = Your sketch, "{ $sketch }", is the closest of the shapes to the measured curve (on average { $percent } % of the plot's height away).
inv-curve-verdict-other = Your sketch, "{ $sketch }", lies on average { $percent } % of the plot's height from the measured curve; the closest shape is "{ $closest }" ({ $closest_percent } %).
inv-csv-curve-low = curve x={ $x } 95% low
inv-csv-curve-high = curve x={ $x } 95% high
inv-loners = loners (Individual tank)
inv-school = school (Group tank)
inv-catches-summary = In { $secs } simulated seconds the shark caught { $loners } loners and { $school } fish of the school.
inv-row-caught-loners = fish caught, loners (Individual tank)
inv-row-caught-school = fish caught, school (Group tank)
inv-unit-fish = fish
inv-unit-fish-caught = fish caught
inv-fish-heeded = fish { $fish } (heeded { $count })
inv-alignment-summary = You inspected { $fish }: each reacted only to the few neighbours it saw. Polarization with alignment on (weight { $weight }): { $on }; off: { $off } (means over { $secs } s).
inv-row-alignment-on = polarization, alignment on ({ $weight })
inv-row-alignment-off = polarization, alignment off (0)
inv-row-heeded = neighbours fish { $fish } heeded
inv-unit-polarization = polarization (0-1)
inv-what-polarization = the polarization
inv-what-speed = speed
inv-curve-point = { $value } at { $x }
inv-curve-summary = Measured { $what }: { $first } ({ $x_label }), { $last } at the top, highest { $peak }.
inv-curve-none = No point of { $what } was measured.
inv-row-curve = { $y_label } at { $x_label } { $x }
inv-race-summary = After { $secs } s the copy that practised { $tries } tries swam { $last } m; the best of the others { $best } m ({ $margin } %). The copy with { $first_tries } tries swam { $first } m.
inv-row-distance = distance after { $tries } tries
inv-unit-metres-swum = metres swum
inv-status-catches = { $t } of { $secs } simulated seconds
inv-status-sweep = run { $run } of { $runs } of the experiment
inv-status-tail-beat = swimming at { $hz } beats a second ({ $k } of { $total })
inv-status-open-learning = open the learning lab
inv-status-race = the race: { $t } of { $secs } s
inv-status-practising = practising the first drill: { $tries } of { $total } tries
inv-status-alignment = alignment on { $on }/{ $secs } s, off { $off }/{ $secs } s
inv-experiment-refused = the investigation's experiment: { $error }

## Steps refused (src/investigation/mod.rs) and links (link.rs).

inv-error-no-prediction = commit a prediction first: the run starts only after you have predicted
inv-error-locked = the prediction is locked: it was committed before the run
inv-error-no-such-answer = answer { $choice } does not exist: there are { $count } answers
inv-error-wrong-step = not now: this is the { $step } step
inv-error-no-result = the run has not finished yet
inv-step-name-intro = intro
inv-step-name-predict = predict
inv-step-name-run = run
inv-step-name-explain = explain
inv-step-name-reveal = reveal
inv-error-no-investigation = no investigation is open
inv-link-unknown = there is no investigation '{ $id }'; the investigations are: { $known }
inv-link-not-an-id = investigation: expected an id such as "why-school" (or null to close it), got { $got }

## The window (src/ui/investigation_panel.rs).

inv-button = Investigations: predict, run, explain
    .help = Guided lessons: predict what will happen, run it, explain what you saw, and find out what scientists found
inv-window-title = Investigation: { $title }
inv-list-title = Investigations
inv-list-intro = Predict, run, explain. Each takes one lesson's part; the tank stays yours to explore afterwards.
inv-continue = Continue: { $title } »
    .help = Back to the investigation you were doing
inv-minutes = about { $minutes } minutes
inv-record = Download my record
    .help = One web page with your predictions, the measured numbers, the plots and your explanations, for your teacher; it opens without Shoal
inv-record-csv = Numbers (CSV)
    .help = The measured numbers of your runs, for a spreadsheet
inv-record-next = open it in any web browser
inv-record-csv-next = open it with a spreadsheet
inv-next-predict = Next: predict »
inv-commit = Commit my prediction (it locks)
    .help = Once committed, your prediction is locked: it cannot change
    .disabled = Choose an answer first
inv-run = Run »
    .help = Start the run: the measurement begins now
    .disabled = Commit a prediction first
inv-your-prediction = Your prediction (locked): { $prediction }
inv-next-explain = Next: explain »
inv-question-of = Question { $number } of { $count }
inv-answer-hint = Your answer (it goes in your record)
inv-to-reveal = What did scientists find? »
inv-next-question = Next question »
inv-found = What scientists found
inv-your-run = Your run: { $summary }
inv-sandbox = The tank is yours now: every control works. Change something and watch what it does.
inv-others = Other investigations
inv-step-look = 1 Look
inv-step-predict = 2 Predict
inv-step-run = 3 Run
inv-step-explain = 4 Explain
inv-step-found = 5 Found
inv-alignment-off = Alignment off
    .help = Set the alignment urge to 0: fish stop copying their neighbours
inv-alignment-on = Alignment on
    .help = Put the alignment urge back
inv-alignment-so-far = Polarization so far: alignment on { $on }, off { $off }. Fish clicked: { $fish }
inv-none-clicked = none yet (click a fish in the tank)

## The window's plots (src/ui/investigation_plot.rs).

inv-plot-your-sketch = your sketch
inv-plot-tries = tries practised
inv-plot-measured = measured
inv-plot-interval = 95 % interval
inv-plot-your-prediction = your prediction
inv-plot-simulated-seconds = simulated seconds

## The student's record (src/investigation/record.rs).

inv-record-title = My Shoal investigations
inv-record-intro = Predict, observe, explain: each prediction was locked before its run started. Every number below was measured by Shoal's simulation during the run.
inv-record-none = No investigation has been done yet.
inv-record-my-prediction = My prediction
inv-record-locked = { $prediction } (locked before the run)
inv-record-no-prediction = No prediction yet.
inv-record-measured = What was measured
inv-record-not-finished = The run has not finished.
inv-record-my-explanations = My explanations
inv-record-no-answer = (no answer)
inv-record-table-measured = measured
inv-record-table-value = value
inv-record-table-unit = unit
inv-record-svg-measured = measured (bars: 95 % interval)
inv-record-svg-prediction = my prediction (dashed)
inv-record-svg-seconds = simulated seconds (0 to { $secs })
inv-record-csv-title = # Shoal: the measured numbers of my investigations (one row per number)
inv-record-csv-predicted = # { $id }: predicted "{ $prediction }"
inv-record-byline = { $name }, { $date } at { $time }
inv-record-no-name = No name given
inv-record-seeds = Seed: { $seeds }.
inv-record-rerun = Open this run again in Shoal (same settings and seed)
inv-record-csv-run = # { $id }: seed { $seeds }; run it again: { $link }
inv-student-name = Your name, for your record:
    .hint = First and last name
    .help = Written at the top of your record and in its file name. Only this browser remembers it; it is never sent anywhere.
