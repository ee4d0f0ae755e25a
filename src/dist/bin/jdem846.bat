@echo off
rem jdem846 launcher for Windows: runs lib\jdem846-cli.jar. On JDK 19 and later the JVM keeps an application
rem class-data archive in %LOCALAPPDATA%\jdem846 for faster starts (JDK 17 and 18 ignore those options).
rem Environment: JAVA_HOME (else java on the PATH), JDEM846_OPTS (extra JVM options, e.g. -Xmx8g).
setlocal
set "JAR=%~dp0..\lib\jdem846-cli.jar"
if defined JAVA_HOME (set "JAVA=%JAVA_HOME%\bin\java.exe") else (set "JAVA=java")
set "CACHE=%LOCALAPPDATA%\jdem846"
if not exist "%CACHE%" mkdir "%CACHE%" 2>nul
"%JAVA%" -XX:+IgnoreUnrecognizedVMOptions -XX:+AutoCreateSharedArchive "-XX:SharedArchiveFile=%CACHE%\jdem846.jsa" -Xshare:auto -Xlog:cds=off -Xlog:cds+dynamic=off %JDEM846_OPTS% -jar "%JAR%" %*
exit /b %ERRORLEVEL%
