@echo off
rem Shoal from a USB stick, on Windows: serves the app on this computer and
rem opens the browser. Close this window to stop it.
cd /d "%~dp0"
where py >nul 2>nul && (py -3 serve.py %* & goto :eof)
where python >nul 2>nul && (python serve.py %* & goto :eof)
echo Shoal needs Python 3 to serve itself: https://www.python.org/downloads/
echo Shoal necesita Python 3 para servirse: https://www.python.org/downloads/
pause
