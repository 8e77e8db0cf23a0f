# La ventana Experimento… (barridos de un ajuste por niveles y semillas), sus
# gráficas y su tabla, y los errores de un diseño o de un enlace de experimento.

experiment-open = Experimento…
    .help = Corre el tanque muchas veces: cambia un ajuste por niveles y semillas, mide el cardumen y grafica la respuesta
experiment-window = Experimento
experiment-intro = Corre este tanque muchas veces: cambia un ajuste, repite cada nivel con otras semillas y mide el cardumen. El tanque de la pantalla sigue nadando.
experiment-running-design = { $name }: { $runs ->
    [one] { $runs } corrida
   *[other] { $runs } corridas
} de { $secs } s
experiment-cannot-start = No se puede empezar: { $field }: { $reason }
experiment-start = Empezar
    .help = Corre cada nivel con cada semilla, un poco en cada cuadro
experiment-save-design = Guardar diseño
    .help = Descarga este diseño como archivo: shoal-lab lo corre en muchos núcleos
experiment-save-design-next = córrelo con shoal-lab run, o guárdalo para la próxima vez
experiment-measuring-pace = midiendo el ritmo…
experiment-progress = { $done } de { $total ->
    [one] { $total } corrida
   *[other] { $total } corridas
} · { $left }
experiment-progress-paused = { $done } de { $total ->
    [one] { $total } corrida
   *[other] { $total } corridas
} · en pausa
experiment-pause = Pausa
    .help = Detiene las corridas por ahora
experiment-resume = Reanudar
experiment-cancel = Cancelar
    .help = Detiene todo para siempre; las corridas ya terminadas se conservan
experiment-cancelled = Cancelado: abajo se conservan las { $done } corridas completadas de { $total }.
experiment-done = { $count ->
    [one] Listo: { $count } corrida.
   *[other] Listo: { $count } corridas.
}
experiment-watching = Viendo la corrida con { $levels }, semilla { $seed }, desde su inicio.
experiment-download-csv = Descargar CSV
    .help = Los números de cada corrida, una fila por corrida y medida
experiment-download-csv-next = ábrelo con una hoja de cálculo
experiment-new = Nuevo experimento
    .help = Guarda estos resultados y diseña otro (descárgalos antes)
experiment-copy-link = Copiar enlace
    .help = Copia un enlace que abre Shoal en este experimento y lo vuelve a correr: las mismas corridas, los mismos números
experiment-name = Nombre
experiment-vary = Variar
    .help = El ajuste que cambia de una corrida a otra
experiment-then = Luego
experiment-second = y un segundo ajuste
    .help = Una curva por cada nivel de un segundo ajuste
experiment-seeds = Semillas
    .help = Cada nivel se corre una vez por semilla: los mismos peces, un inicio distinto
experiment-from-seed = desde la semilla
experiment-warmup = Calentamiento
    .help = Segundos de cada corrida antes de medir: el cardumen se forma
experiment-measure-for = Medir durante
    .help = Segundos de cada corrida que se miden después del calentamiento
experiment-measures = Medidas
experiment-mean = promedio
    .help = El promedio durante el tiempo de medición
experiment-final = final
    .help = El valor al final de la corrida
experiment-off-and-on = apagado y encendido
experiment-range-from = de
experiment-range-to = a
experiment-range-in = en
experiment-range-levels = niveles
experiment-runs = Corridas
experiment-runs-value = { $levels ->
    [one] { $levels } nivel
   *[other] { $levels } niveles
} × { $seeds ->
    [one] { $seeds } semilla
   *[other] { $seeds } semillas
} = { $runs }
experiment-steps-per-run = Pasos por corrida
experiment-steps-value = { $warmup } de calentamiento + { $measured } medidos ({ $dt } s cada uno)
experiment-time = Tiempo
experiment-time-help = { $compute } de cálculo, hecho a { $ms } ms por cuadro mientras el tanque sigue nadando (más en una computadora que dibuja menos de 30 cuadros por segundo)
experiment-duration-under-second = menos de un segundo
experiment-duration-secs = unos { $value } s
experiment-duration-min = unos { $value } min
experiment-duration-hours = unas { $value } h

# Las medidas que no son las de las gráficas (esas conservan los nombres de
# las gráficas de métricas): src/experiment/measure.rs.
experiment-measure-distance-swum = Distancia nadada (m)
    .help = Qué tan lejos nadó el pez promedio mientras se medía, en metros
experiment-measure-catches = Presas atrapadas
    .help = Cuántos peces atraparon los tiburones (o los depredadores) mientras se medía
experiment-measure-food-eaten = Plancton comido
    .help = Cuántas partículas de plancton comieron los peces mientras se medía
experiment-measure-spawnings = Desoves
    .help = Cuántas veces una pareja desovó (puso y fecundó huevos) mientras se medía
experiment-measure-missed-strikes = Ataques fallidos
    .help = Cuántas veces un depredador atacó y falló, confundido por el montón de presas
experiment-measure-fish-collisions = Choques entre peces
    .help = Cuántas veces chocaron dos peces mientras se medía
experiment-measure-prey-alive = Presas vivas
    .help = Cuántos peces presa siguen vivos

# Los resultados: gráficas y tabla.
experiment-level-on = encendido
experiment-level-off = apagado
experiment-no-run-yet = Todavía no ha terminado ninguna corrida.
experiment-plot-title = { $measure } · { $summary }
experiment-no-factor = (ningún factor)
experiment-interval-about = Barras y [corchetes]: un intervalo del 95 %. Si corrieras muchas más semillas, su promedio caería casi seguro dentro de él. Se calcula volviendo a sortear entre las semillas que corriste (un bootstrap), así que nunca se sale de lo que la medida puede valer.
experiment-few-seeds = { $count ->
    [one] Solo { $count } semilla por nivel: estos intervalos son aproximados. Usa 5 semillas o más para una respuesta más segura.
   *[other] Solo { $count } semillas por nivel: estos intervalos son aproximados. Usa 5 semillas o más para una respuesta más segura.
}
experiment-table-title = Promedio de las semillas [intervalo del 95 %]
experiment-table-watch = ver una corrida
experiment-interval = { $mean } [{ $low }; { $high }]
experiment-seed-button = semilla { $seed }
    .help = Pon el tanque en este nivel y esta semilla, desde el inicio: mira esta misma corrida

# Por qué se rechaza un diseño: el campo y luego la razón.
experiment-error = { $field }: { $reason }
experiment-error-json-place = (archivo, línea { $line }, columna { $column })
experiment-error-too-many-factors = { $count } factores: como máximo { $max }
experiment-error-factor-twice = '{ $key }' ya es un factor
experiment-error-no-sample = en { $secs } s no cabe ninguna muestra de las métricas: mide al menos { $min } s
experiment-error-too-many-runs = { $runs } corridas (niveles × semillas): como máximo { $max }
experiment-error-link-empty = el enlace está vacío
experiment-error-seeds-and-count = da seeds (una lista) o count (y first_seed), no ambos
experiment-error-first-seed-with-list = va con count, no con una lista de semillas
experiment-error-how-many-seeds = di cuántas semillas (count) o cuáles (seeds)
experiment-error-no-replicates = no hay réplicas: al menos una semilla
experiment-error-too-many-seeds = { $count } semillas: como máximo { $max }
experiment-error-seed-range = la semilla { $seed } está fuera del rango: elige entre 0 y { $max }
experiment-error-seed-twice = la semilla { $seed } aparece dos veces: una réplica repetiría una corrida
experiment-error-no-measures = no hay nada que medir: nombra al menos una medida
experiment-error-unknown-measure = medida desconocida '{ $name }'; las medidas son: { $known }
experiment-error-measure-not-here = '{ $name }' no se mide en la escena { $scene } ({ $id }); ahí se mide: { $known }
experiment-error-nothing = nada
experiment-error-unknown-summary = resumen desconocido '{ $name }': elige mean, final o series
experiment-error-measured-twice = { $name } ({ $summary }) ya se mide
experiment-error-unknown-setting-there = ajuste desconocido; los ajustes de ahí son: { $known }
experiment-error-seed-factor = las semillas son las réplicas: ponlas en replicates
experiment-error-display-only = '{ $key }' cambia cómo se muestra una corrida, no lo que pasa en ella
experiment-error-selection = '{ $key }' elige el pez que se muestra en detalle, no lo que pasa en una corrida
experiment-error-does-not-act = '{ $key }' no actúa en la escena { $scene } ({ $id }); sus ajustes ahí están bajo '{ $section }.'
experiment-error-unknown-setting = ajuste desconocido
experiment-error-not-a-slider = '{ $key }' no es un número ni un ajuste de encendido y apagado: un factor cambia un control deslizante o un interruptor
experiment-error-no-levels = no hay niveles: al menos uno
experiment-error-too-many-levels = { $count } niveles: como máximo { $max }
experiment-error-level-not-switch = { $level } no es un nivel de '{ $key }': acepta true o false
experiment-error-level-not-number = { $level } no es un nivel de '{ $key }': acepta números
experiment-error-level-twice = el nivel { $level } aparece dos veces
experiment-error-range-field = campo desconocido: un rango tiene from, to y steps
experiment-error-not-a-number = falta, o no es un número
experiment-error-not-whole = falta, o no es un número entero
experiment-error-one-step = un solo paso no puede ir de un valor a otro: al menos 2
experiment-error-levels-shape = da una lista ([0, 50, 100]) o un rango ({"{"}"from": 0, "to": 100, "steps": 3{"}"})
experiment-error-secs-range = { $secs } está fuera del rango: elige entre 0 y { $max } s
experiment-error-zero-secs = 0 s no miden nada

# Por qué no se pudo abrir un enlace de experimento.
experiment-link-empty = el enlace no contiene ningún experimento
experiment-link-refused = su experimento no se puede correr: { $reason }
