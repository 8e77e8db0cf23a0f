# *Acerca de esta escena* (src/ui/about.rs, src/ui/about_text.rs), el aviso
# del código QR para compartir (src/ui/qr.rs) y el título de la ventana de
# escritorio (src/main.rs).

about-app-title = Shoal — un laboratorio virtual de etología
about-button = ℹ Acerca de esta escena
    .help = Qué muestra esta escena, cómo funciona, qué observar y qué probar
about-window-title = Acerca de: { $scene }
about-how = Cómo funciona
about-notice = Cosas para observar
about-try = Cosas para probar
about-equations = Las ecuaciones
about-equations-docs = Cada constante, de dónde sale y en qué se aparta Shoal de los artículos científicos: la carpeta docs/ del proyecto.
about-references = Referencias
about-qr-too-long = el enlace es demasiado largo para un código QR ({ $count ->
        [one] { $count } carácter
       *[other] { $count } caracteres
    }): acorta la pregunta o quita algunas reglas

# Referencias (bajo *Referencias*): los títulos de los artículos quedan como se publicaron.
about-ref-tu-terzopoulos = Tu, X. & Terzopoulos, D. (1994). Artificial fishes: physics, locomotion, perception, behavior. Proceedings of SIGGRAPH 94, 43–50; y Artificial Life 1(4), 327–351.
about-ref-lim-tan = Lim, L. & Tan, K. Virtual ethology: simulation of aquatic animal heterogeneous behaviours as particle-based autonomous agents (SIMBA); y (2018) Understanding steering mechanisms for simulating fish behaviours. JISTM 3(8).
about-ref-reynolds = Reynolds, C. W. (1987). Flocks, herds and schools: a distributed behavioral model. Computer Graphics 21(4), 25–34.
about-ref-couzin = Couzin, I. D., Krause, J., James, R., Ruxton, G. D. & Franks, N. R. (2002). Collective memory and spatial sorting in animal groups. Journal of Theoretical Biology 218, 1–11.
about-ref-ballerini = Ballerini, M. et al. (2008). Interaction ruling animal collective behavior depends on topological rather than metric distance. PNAS 105(4), 1232–1237.
about-ref-pitcher = Pitcher, T. J. & Partridge, B. L. (1979). Fish school density and volume. Marine Biology 54, 383–394.
about-ref-landeau = Landeau, L. & Terborgh, J. (1986). Oddity and the 'confusion effect' in predation. Animal Behaviour 34, 1372–1380.
about-ref-videler = Videler, J. J. (1993). Fish Swimming. Chapman & Hall.
about-ref-kirkpatrick = Kirkpatrick, S., Gelatt, C. D. & Vecchi, M. P. (1983). Optimization by simulated annealing. Science 220, 671–680.

# Las ecuaciones: cada mensaje es el nombre; su .formula, la fórmula y lo que significan sus letras.
about-eq-seek = Buscar una velocidad deseada
    .formula = dirección = v_deseada − v, luego limitada a la mayor fuerza de dirección (8 m/s² por defecto); v es la velocidad del pez. Ninguna velocidad pasa de la velocidad máxima.
about-eq-wander = Deambular
    .formula = deseo = hacia un punto de un círculo delante del pez; el ángulo del punto en el círculo se mueve un poco al azar en cada paso, así que el camino serpentea.
about-eq-containment = Contención y evasión
    .formula = mira hacia adelante a lo largo del camino; si fuera a quedar a menos de 1 m del vidrio, la arena o la superficie, o a chocar con una roca, gira para seguir el obstáculo en vez de ir contra él.
about-eq-alignment = Alineación
    .formula = deseo = el rumbo medio de los (hasta 7) vecinos más cercanos que ve, en el que los más cercanos cuentan más, por la velocidad máxima.
about-eq-cohesion = Cohesión
    .formula = deseo = hacia el centro de esos vecinos (y del cardumen lejano que ve).
about-eq-separation = Separación
    .formula = deseo = alejarse de cada vecino que esté más cerca que el espacio personal (0,8 m), con más fuerza cuanto más cerca esté.
about-eq-weights = Pesos
    .formula = el control deslizante w de cada impulso (0–100) lo escala: un control de contención, alineación, cohesión o separación al máximo da el 25 % de la mayor fuerza de dirección, y uno de evasión al máximo, el 100 %.
about-eq-blended = Mezclado (directo)
    .formula = aceleración = Σ wᵢ · impulsoᵢ sobre los cinco impulsos, luego limitada.
about-eq-classic = Clásico
    .formula = un impulso por paso: el de mayor wᵢ × |impulsoᵢ| actúa solo, con toda su parte.
about-eq-direct-alternate = Directo alterno
    .formula = se sortea ρ en [0, 1]; actúa cada impulso con peso wᵢ ≥ ρ (los pesos como partes de 100).
about-eq-monte-carlo = Monte Carlo
    .formula = se sortea ρ en [0, Σw); actúa el único impulso cuya porción de 0…Σw contiene a ρ (así que se elige con probabilidad wᵢ / Σw).
about-eq-polarization = Polarización
    .formula = p = |Σ v̂ᵢ| / N, la longitud del rumbo medio: 1 cuando todos los peces nadan hacia el mismo lado, cerca de 0 cuando cada uno apunta para un lado distinto.
about-eq-milling = Remolino
    .formula = m = |Σ r̂ᵢ × v̂ᵢ| / N alrededor del centro de cada grupo (r̂ᵢ apunta del centro al pez i): 1 cuando los peces dan vueltas alrededor de su centro como una dona. Un grupo cuenta solo si tiene al menos 5 peces a menos de 1,5 largos de cuerpo entre sí, y solo su giro más allá del azar: (m − 1/√k) / (1 − 1/√k) para un grupo de k peces.
about-eq-nearest = Vecino más cercano y grupos
    .formula = NND = la distancia media de cada pez a su vecino más cercano, en largos de cuerpo; un grupo son peces unidos por huecos de dos largos de cuerpo como máximo.
about-eq-springs = Resortes
    .formula = f = c · (|r| − l) · r / |r|: un resorte de rigidez c y longitud en reposo l junta sus dos masas cuando se estira y las separa cuando se aprieta (r va de una masa a la otra). c = 38 para los resortes cruzados, 28 para los músculos y 30 para los demás.
about-eq-mass-motion = Movimiento de cada masa
    .formula = m ẍ + γ ẋ = Σ fuerzas de los resortes + fuerza del agua, con masas m de 0,165 a 11 y amortiguamiento γ = 0,05; se resuelve de forma implícita (cada paso calcula juntas las nuevas velocidades), así que los resortes rígidos no pueden dispararse sin control.
about-eq-muscles = Músculos
    .formula = un músculo se contrae acortando su longitud en reposo: reposo = l − u · (l − l_min), con u en [0, 1] fijado por el controlador motor y l_min su longitud totalmente contraída.
about-eq-water = Agua
    .formula = en cada triangulito de piel, f = −A (n · v) n cuando el triángulo se mueve contra el agua (A su área, n su normal hacia afuera, v su velocidad a través del agua); nada cuando se aleja de ella. Una cola que bate de lado recibe un empuje hacia adelante.
about-eq-fins = Aletas
    .formula = F = −A |v| cos θ · n: inclinar las aletas pectorales hacia arriba hace subir y hacia abajo hace bajar; puestas de frente a la corriente, frenan.
about-eq-hunger = Hambre
    .formula = H = min(1 − n · (1 − p₀ Δt_H) / α, 1): n la comida que ingirió la última vez que comió, Δt_H el tiempo desde entonces (en las unidades de tiempo del artículo, de 1/40 s), p₀ qué tan rápido se digiere la comida, α el apetito.
about-eq-libido = Libido
    .formula = L = min(p₁ Δt_L · (1 − H), 1): Δt_L el tiempo desde el último apareamiento; un pez con hambre tiene poca libido.
about-eq-fear = Miedo
    .formula = F = min(Σᵢ min(D₀ / dᵢ, 1), 1) sobre los depredadores que ve, con dᵢ sus distancias.
about-eq-intention = El generador de intenciones
    .formula = en orden: algo en su camino → esquivar; F > f₀ → formar cardumen (si es de los que forman cardúmenes y el peor miedo está por debajo de f₁) o huir; max(H, L) > r → comer o aparearse, lo que sea mayor; agua que no le gusta → irse; si no, deambular.
about-eq-shark-choice = La elección del tiburón
    .formula = caza a la presa k con el menor C = d · (1 + 0,5 S + 0,2 E / π): d la distancia, S = 1 si esa presa nada en un cardumen, E el giro que necesitaría. Un cardumen cuesta más.
about-eq-her-choice = La elección de ella
    .formula = una hembra ordena a los machos que ve por 0,2 d − 10 L (d la distancia, L la longitud de él en metros; gana el menor): medir 10 cm más vale lo mismo que estar 5 m más cerca.
about-eq-objective = Lo que intenta mejorar
    .formula = E = ∫ (μ₁ E_u + μ₂ E_v) dt: E_v mide qué tan lejos está de la meta del ejercicio (la distancia que falta, o la diferencia con la velocidad o el giro pedidos), E_u = ½(ν₁ |u̇|² + ν₂ |ü|²) castiga los movimientos bruscos de los músculos. Más bajo es mejor.
about-eq-muscle-controls = El control de los músculos
    .formula = la contracción u(t) de cada uno de los 12 músculos se da en 15 momentos, unidos por una curva suave (un spline).
about-eq-annealing = Recocido simulado
    .formula = cambia un poco al azar los 15 × 12 números; conserva el cambio si E baja; conserva uno peor con probabilidad e^(−ΔE / T), donde la temperatura T baja a lo largo de los intentos, así que al principio explora y más tarde solo mejora.
about-eq-abstraction = Abstracción
    .formula = una transformada de Fourier encuentra los ritmos principales de los movimientos aprendidos; quedarse solo con ellos da un controlador sencillo, e interpolar entre ejercicios da un mapa de velocidad y dirección.

# Acuario
about-aquarium-what = Un acuario de peces que deambulan. Cada pez es un punto con una velocidad y un rumbo, dibujado como un pez. Nada les dice que formen un cardumen.
about-aquarium-how = Cada 1/60 de segundo, cada pez elige una dirección deseada: un poco de deambular (un punto en un círculo delante de él que se mueve al azar), más alejarse del vidrio, la arena y la superficie, y rodear rocas y pilares. Gira hacia lo que desea con toda la fuerza que le permite su capacidad de giro, sin ir nunca más rápido que su velocidad máxima.
about-aquarium-notice-1 = Los peces giran antes de llegar al vidrio: miran hacia adelante a lo largo de su camino.
about-aquarium-notice-2 = Esquivan un pilar rodeándolo en vez de detenerse frente a él.
about-aquarium-notice-3 = Dos peces que se encuentran no se alinean: no tienen ningún impulso de seguirse.
about-aquarium-try-1 = Pon Peces en 2000 y mira desde arriba (arrastra la vista).
about-aquarium-try-2 = Abre el Laboratorio de cardúmenes y compara: ¿qué hacen sus peces que estos no hacen?

# Laboratorio de cardúmenes
about-schooling-what = Un laboratorio virtual de etología: peces que siguen cinco impulsos, como en SIMBA de Lim y Tan. Cambia los impulsos y mira cómo se forma un cardumen, o cómo se deshace. Compara dos tanques que solo se diferencian en los impulsos.
about-schooling-how = Cada pez ve a sus vecinos (hasta 5 m, en todas direcciones menos en un cono ciego detrás de él) y hace caso a los 7 más cercanos que ve. Cada uno de cinco impulsos desea una velocidad: quedarse en el tanque (contención), nadar como los vecinos (alineación), mantenerse cerca (cohesión), guardar algo de espacio (separación) y esquivar rocas y otros peces (evasión). Los controles deslizantes les dan su peso, y el modo de control dice cómo se combinan: todos juntos o uno a la vez. No hay líder: todos los peces siguen las mismas reglas y solo reaccionan a los pocos vecinos que ven.
about-schooling-notice-1 = El ajuste Grupo forma un cardumen: polarización cerca de 0,8, un solo grupo y vecinos a más o menos un largo de cuerpo. Individual los deja dispersos.
about-schooling-notice-2 = Un cardumen gira como si fuera uno solo, pero ningún pez decide a dónde va.
about-schooling-notice-3 = Con un tiburón, los peces de un cardumen son atrapados con menos frecuencia: al tiburón lo confunden los muchos peces alrededor de su objetivo.
about-schooling-try-1 = Pon la alineación en 0 en el tanque Grupo. ¿Qué le pasa a la polarización?
about-schooling-try-2 = Compara dos tanques: ¿quién pierde menos peces ante un tiburón, el cardumen o los solitarios?
about-schooling-try-3 = Cambia el modo de control a Monte Carlo y lee las barras de los impulsos.
about-schooling-try-4 = Pon una roca en el camino del cardumen y mira cómo se divide y se vuelve a juntar.

# Peces con física
about-physics-what = Peces con cuerpo: 23 masas unidas por 91 resortes, 12 de ellos músculos, como en Tu y Terzopoulos. Lo único que empuja al pez hacia adelante es el agua contra su cola, que bate.
about-physics-how = Los músculos se acortan y se alargan por turnos en los dos lados y doblan el cuerpo a la izquierda y a la derecha. El agua empuja hacia atrás cada trozo de piel que se mueve contra ella; una cola que barre de lado recibe un empuje que en parte va hacia adelante, y así el pez nada. Un controlador motor convierte una velocidad deseada en cuánto y qué tan rápido tiran los músculos, otro convierte un giro deseado en una curva del cuerpo, y las aletas pectorales hacen subir, bajar y frenar. Los mismos impulsos del laboratorio de cardúmenes le dan a cada pez lo que desea.
about-physics-notice-1 = Selecciona un pez y lee sus doce músculos: los dos lados tiran por turnos.
about-physics-notice-2 = Mostrar fuerzas: el empuje amarillo del agua es mayor en la cola.
about-physics-notice-3 = Un pez no puede frenar en seco ni girar en su lugar: tiene un cuerpo que mover.
about-physics-try-1 = Dirige un pez a mano: ¿cómo cambia su velocidad con el control de velocidad de nado?
about-physics-try-2 = Activa la corriente y mira cómo se deja llevar un pez que deja de nadar.
about-physics-try-3 = Gira a la izquierda 30° y luego 90°: ¿cuál tarda más?

# Arrecife
about-reef-what = Un arrecife de peces con mente, como en Tu y Terzopoulos: ven, les da hambre, se asustan y cortejan. Cada uno decide qué hacer según lo que ve y cómo se siente. Haz clic en un pez para mirar dentro de su cabeza.
about-reef-how = Cada pez ve en todas direcciones menos hacia atrás, hasta donde el agua está clara, y no a través de rocas ni de otros peces. El hambre crece a medida que digiere su comida, la libido con el tiempo desde el último apareamiento y el miedo con los depredadores cercanos. Un generador de intenciones elige una intención en un orden fijo (esquivar, huir o formar cardumen, comer o aparearse, irse, deambular), recuerda una que quedó interrumpida, y una rutina de comportamiento maneja los controladores motores del cuerpo: nadar, girar, aletas.
about-reef-notice-1 = Un cardumen asustado huye todo junto; un tiburón que ataca a una multitud a menudo falla.
about-reef-notice-2 = Las hembras en cortejo eligen al macho más grande (el registro lo dice).
about-reef-notice-3 = Un pez que rodea una roca vuelve a la comida que buscaba: se acuerda.
about-reef-try-1 = Abre Depredador y cardumen y Saltar al momento: mira la captura del tiburón.
about-reef-try-2 = En Mentes, haz que la presa sea tímida o valiente y cuenta las capturas.
about-reef-try-3 = Enturbia el agua (Visibilidad): ¿encuentran los peces menos comida?

# Laboratorio de aprendizaje
about-learning-what = Cómo aprende a nadar un pez, como en Tu y Terzopoulos: empieza con movimientos de los músculos al azar y se queda con lo que funciona. Luego compite en una carrera contra copias de sí mismo que practicaron menos.
about-learning-how = Un ejercicio fija una meta (nadar lejos, nadar a cierta velocidad, girar). El pez prueba un patrón de movimientos de los músculos, mide qué tan bien le fue, cambia un poco el patrón y se queda con el cambio si le fue mejor (y, al principio, a veces aunque le haya ido peor, para no quedarse atascado). A lo largo de miles de intentos encuentra un ritmo como el coletazo de un pez de verdad.
about-learning-notice-1 = El objetivo baja rápido al principio y después despacio.
about-learning-notice-2 = Los movimientos aprendidos son rítmicos: dos o tres ritmos principales los explican.
about-learning-notice-3 = La práctica ayuda mucho al principio y después casi deja de mejorar: en la carrera, las copias que practicaron unos miles de intentos nadan casi igual de rápido.
about-learning-try-1 = Entrena con 90 intentos por ejercicio y luego con 6840: compara la carrera.
about-learning-try-2 = Cambia al nadador entre controladores aprendidos y ajustados a mano.
about-odd = Descripción del modelo (ODD)
    .help = El modelo descrito como los ecólogos describen los modelos basados en agentes (el protocolo ODD, Grimm et al. 2020): propósito, entidades, escalas, orden de los procesos, conceptos de diseño, inicialización, datos de entrada y submodelos. Se abre en una pestaña nueva.
