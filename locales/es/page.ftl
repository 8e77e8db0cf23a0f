# La página fuera del lienzo: sus avisos y los nombres que oye un lector de
# pantalla (src/web/page.rs, src/web/mod.rs, src/web/a11y_dom.rs).

page-could-not-start = Shoal no pudo iniciar
page-no-canvas = La página no tiene un lienzo llamado shoal_canvas.
page-link-error = No se pudo abrir este enlace: { $error }. Shoal empezó con sus ajustes de siempre.
page-no-gpu-title = Shoal necesita gráficos 3D, y este navegador no los ofreció
page-no-gpu-why = Shoal dibuja el acuario con WebGPU o, si falta, con WebGL2. Este navegador no ofreció ninguno de los dos, o están desactivados.
page-no-gpu-where = Funciona en las versiones actuales de Chrome, Edge, Firefox y Safari (versión 15 o posterior) en Windows, macOS, Linux, ChromeOS, Android y iPadOS. Revisa que la aceleración por hardware esté activada (en Chrome: Configuración → Sistema → "Usar aceleración de gráficos cuando esté disponible") y luego vuelve a cargar la página.
page-details = Detalles: { $detail }
page-reload = Volver a cargar Shoal
page-panic-title = Shoal se detuvo por un error interno
page-panic-sorry = Lo sentimos: algo salió mal dentro de Shoal. Si vuelves a cargar la página, empieza de nuevo.
page-panic-details = Detalles para los desarrolladores: { $detail }
page-canvas = El tanque. Las flechas giran la cámara, más y menos acercan y alejan, N selecciona un pez, D describe el tanque, el signo de interrogación muestra todas las teclas.
page-text-agent = Texto que escribes en el campo que estás editando
page-file-not-text = el archivo no es de texto
page-file-unreadable = no se pudo leer el archivo: { $error }

# Antes de que cargue el WebAssembly (web/shoal-page.js guarda una copia de
# estos mensajes, que una prueba compara con este archivo).
page-loading = Llenando el acuario…
page-too-old-title = Este navegador es demasiado antiguo para Shoal
page-too-old-why = Shoal funciona con WebAssembly, que este navegador no admite. Funciona en las versiones actuales de Chrome, Edge, Firefox y Safari (15 o posterior).
page-load-failed-title = Shoal no pudo cargarse
page-load-failed = No se pudo cargar la simulación: { $error }
page-unknown-error = error desconocido
page-slow-title = Shoal está tardando mucho en iniciar
page-slow-why = El acuario no ha empezado después de 60 segundos. Una red lenta o una computadora ocupada pueden causarlo; volver a cargar la página suele ayudar.
