@echo off
rem jdem846 launcher for Windows: runs lib\jdem846-cli.jar. With JAVA_HOME set to a JDK 19 or later, the JVM keeps an
rem application class-data archive in %LOCALAPPDATA%\jdem846 for faster starts (as bin/jdem846 does on JDK 19 to 24;
rem its ahead-of-time caches per command on JDK 25 and its choice of JIT for small jobs are not made here); otherwise
rem it starts as java -jar does.
rem Environment: JAVA_HOME (else java on the PATH), JDEM846_OPTS (extra JVM options, e.g. -Xmx8g), JDEM846_CDS=off
rem (no archive).
setlocal
set "JAR=%~dp0..\lib\jdem846-cli.jar"
set "JAVA=java"
set "CDS="
set "MAJOR="
if not defined JAVA_HOME goto run
set "JAVA=%JAVA_HOME%\bin\java.exe"
if /i "%JDEM846_CDS%"=="off" goto run
if not exist "%JAVA_HOME%\release" goto run
for /f "tokens=2 delims==" %%v in ('findstr /b "JAVA_VERSION=" "%JAVA_HOME%\release"') do set "JV=%%~v"
if not defined JV goto run
for /f "delims=." %%m in ("%JV%") do set "MAJOR=%%m"
if not defined MAJOR goto run
if %MAJOR% LSS 19 goto run
set "CACHE=%LOCALAPPDATA%\jdem846"
if not exist "%CACHE%" mkdir "%CACHE%" 2>nul
set CDS=-XX:+AutoCreateSharedArchive "-XX:SharedArchiveFile=%CACHE%\jdem846-%MAJOR%.jsa" -Xlog:cds=off -Xlog:cds+dynamic=off
:run
rem core reflection through native accessors: picocli's start-up on JDK 18+ (see bin/jdem846)
"%JAVA%" %CDS% -Djdk.reflect.useNativeAccessorOnly=true %JDEM846_OPTS% -jar "%JAR%" %*
exit /b %ERRORLEVEL%
