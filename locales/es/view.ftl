# Flechas sobre un pez físico (src/ui/body_overlay.rs).

overlay-wants-to-go = quiere ir
overlay-goes = va
overlay-current = corriente

# Guardar y abrir archivos (src/ui/files.rs).

files-download-failed = La descarga no empezó: { $reason }
files-write-failed = No se pudo guardar { $name }: { $reason }
files-dialog-failed = No se abrió la ventana para elegir archivos: { $reason }
files-read-failed = no se pudo leer { $name }: { $reason }
files-downloading-next = Descargando { $name }: { $next }.
files-downloading = Descargando { $name }.
files-saved = Se guardó { $name } en la carpeta desde la que se abrió Shoal.

# Las opciones de vista para ver mejor (src/ui/seeing.rs).

seeing-started-paused = Movimiento reducido está activado (esta computadora lo pide, o el enlace): los peces esperan en pausa hasta que presiones Reanudar (o Espacio). Vista → Reducir movimiento lo desactiva.
seeing-high-contrast = Alto contraste
    .help = Texto blanco sobre negro, bordes marcados alrededor de cada control y un anillo amarillo grueso alrededor del que tiene el teclado: más fácil de leer en un proyector desteñido o si ves poco
seeing-reduce-motion = Reducir movimiento
    .help = Imágenes más tranquilas para quien se siente mal con el movimiento en pantalla: la luz sobre la arena deja de titilar, una cámara que sigue a un pez solo se mueve cuando el pez se acerca al borde, y los paneles se abren sin deslizarse. Los peces siguen nadando: Pausa (Espacio) los detiene
