package io.github.jdem846.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.testing.TestJvm;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The command line shows Apache SIS's log records with {@code --verbose} only, through the logging configuration it
 * names for the log manager to read when something first logs ({@link LibraryLogConfig}), or added to one the JVM
 * was given. A fresh JVM with {@code SIS_DATA} unset: writing the {@code .prj} of a GridFloat makes SIS warn about
 * it.
 */
class LibraryLogConfigTest {

    private static final String DEM = "testdata/dem/bigtujunga_srtm30m_utm11n.flt";

    @Test
    void sisIsQuietWithoutVerbose(@TempDir Path dir) throws Exception {
        Run run = hillshade(dir, List.of(), List.of());
        assertEquals(0, run.exit, run.stderr);
        assertTrue(Files.isRegularFile(dir.resolve("out.prj")), "the .prj is written");
        assertEquals("", run.stderr);
    }

    @Test
    void verboseShowsSisThroughTheJdksConsoleHandler(@TempDir Path dir) throws Exception {
        Run run = hillshade(dir, List.of(), List.of("--verbose"));
        assertEquals(0, run.exit, run.stderr);
        assertTrue(run.stderr.contains("SIS_DATA"), run.stderr);
        assertTrue(run.stderr.contains("jdem846: timing:"), run.stderr);
    }

    @Test
    void aConfigurationOfTheUsersOwnGetsSisLevelAdded(@TempDir Path dir) throws Exception {
        Path config = dir.resolve("logging.properties");
        Files.writeString(config, "handlers = java.util.logging.ConsoleHandler\n.level = INFO\n");
        Run quiet = hillshade(dir, List.of("-Djava.util.logging.config.file=" + config), List.of());
        assertEquals(0, quiet.exit, quiet.stderr);
        assertFalse(quiet.stderr.contains("SIS_DATA"), quiet.stderr);
        Run verbose = hillshade(dir, List.of("-Djava.util.logging.config.file=" + config), List.of("--verbose"));
        assertTrue(verbose.stderr.contains("SIS_DATA"), verbose.stderr);
    }

    private record Run(int exit, String stderr) {
    }

    private static Run hillshade(Path dir, List<String> jvmOptions, List<String> options) throws Exception {
        List<String> command = new ArrayList<>(List.of(TestJvm.java(), "-Djava.awt.headless=true"));
        command.addAll(jvmOptions);
        command.addAll(List.of("-cp", TestJvm.classPath(), Main.class.getName(), "hillshade", DEM, "-o",
                dir.resolve("out.png").toString(), "--world-file", "-q"));
        command.addAll(options);
        ProcessBuilder builder = new ProcessBuilder(command).redirectOutput(dir.resolve("stdout.txt").toFile())
                .redirectError(dir.resolve("stderr.txt").toFile());
        builder.environment().remove("SIS_DATA");
        Process p = builder.start();
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "finished");
        return new Run(p.exitValue(), Files.readString(dir.resolve("stderr.txt"), StandardCharsets.UTF_8));
    }
}
