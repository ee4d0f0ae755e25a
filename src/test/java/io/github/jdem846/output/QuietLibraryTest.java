package io.github.jdem846.output;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.geo.CrsResolver;
import io.github.jdem846.testing.TestJvm;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The library writes nothing on stderr: a fresh JVM (Apache SIS not yet started, java.util.logging as the JDK
 * configures it, {@code SIS_DATA} unset) writes a PNG with its {@code .prj} through the library API. An application
 * that configures SIS's loggers itself gets SIS's warning.
 */
class QuietLibraryTest {

    /** The embedding application: writes {@code args[0]} with all sidecars, for a CRS made from its EPSG code. */
    public static final class PrjWriter {
        public static void main(String[] args) throws IOException {
            GeoReference geo = new GeoReference(380000, 3800000, 381000, 3799000,
                    CrsResolver.fromEpsg(32611).orElseThrow());
            WriteResult r = ImageOutput.writeRgba(Path.of(args[0]), new int[4], 2, 2, geo,
                    WriteOptions.defaults().withSidecars(WriteOptions.Sidecars.ALWAYS));
            System.out.println(r.sidecars());
        }
    }

    @Test
    void writingAPrjPrintsNothingOnStderr(@TempDir Path dir) throws Exception {
        Run run = writeInFreshJvm(dir, List.of());
        assertEquals(0, run.exit, run.stderr);
        assertTrue(Files.isRegularFile(dir.resolve("out.prj")), run.stdout);
        assertEquals("", run.stderr);
    }

    @Test
    void anApplicationThatConfiguresSisLoggingSeesItsWarning(@TempDir Path dir) throws Exception {
        Path config = dir.resolve("logging.properties");
        Files.writeString(config, "handlers = java.util.logging.ConsoleHandler\norg.apache.sis.level = INFO\n");
        Run run = writeInFreshJvm(dir, List.of("-Djava.util.logging.config.file=" + config));
        assertEquals(0, run.exit, run.stderr);
        assertTrue(Files.isRegularFile(dir.resolve("out.prj")), run.stdout);
        assertTrue(run.stderr.contains("SIS_DATA"), run.stderr);
    }

    private record Run(int exit, String stdout, String stderr) {
    }

    private static Run writeInFreshJvm(Path dir, List<String> jvmOptions) throws Exception {
        List<String> command = new ArrayList<>(List.of(TestJvm.java(), "-Djava.awt.headless=true"));
        command.addAll(jvmOptions);
        command.addAll(List.of("-cp", TestJvm.classPath(), PrjWriter.class.getName(),
                dir.resolve("out.png").toString()));
        ProcessBuilder builder = new ProcessBuilder(command).redirectOutput(dir.resolve("stdout.txt").toFile())
                .redirectError(dir.resolve("stderr.txt").toFile());
        builder.environment().remove("SIS_DATA");
        Process p = builder.start();
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "finished");
        return new Run(p.exitValue(), Files.readString(dir.resolve("stdout.txt"), StandardCharsets.UTF_8),
                Files.readString(dir.resolve("stderr.txt"), StandardCharsets.UTF_8));
    }
}
