package io.github.jdem846;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.io.Window;
import io.github.jdem846.job.JobListener;
import io.github.jdem846.job.ReliefJob;
import io.github.jdem846.job.ReliefResult;
import io.github.jdem846.job.Sun;
import io.github.jdem846.render.OutputSize;
import io.github.jdem846.render.Scene;
import io.github.jdem846.shadow.ShadowAlgorithm;
import io.github.jdem846.testing.TestJvm;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.ZonedDateTime;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.spi.ToolProvider;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A library user on the module path: a module that {@code requires io.github.jdem846} and nothing else, compiled and
 * run with the main classes and the runtime dependencies on {@code --module-path} (no {@code --add-modules}, no
 * CLI-only jar). It renders README's windowed, real-sun, shadowed job on a test DEM and writes it with its
 * sidecars, which loads Apache SIS, GeoAPI, the sun's position and the image writers; the picture equals the same
 * job run here.
 */
class ModulePathTest {

    private static final String MODULE_INFO = """
            module demo {
                requires io.github.jdem846;
            }
            """;

    private static final String MAIN = """
            package demo;

            import io.github.jdem846.io.Window;
            import io.github.jdem846.job.JobListener;
            import io.github.jdem846.job.ReliefJob;
            import io.github.jdem846.job.ReliefResult;
            import io.github.jdem846.job.Sun;
            import io.github.jdem846.output.WriteOptions;
            import io.github.jdem846.render.OutputSize;
            import io.github.jdem846.render.Scene;
            import io.github.jdem846.shadow.ShadowAlgorithm;
            import java.nio.file.Path;
            import java.time.ZonedDateTime;

            public final class Main {
                public static void main(String[] args) throws Exception {
                    ReliefResult relief = ReliefJob.of(Path.of(args[1]))
                            .withWindow(Window.world(380000, 3790000, 400000, 3800000))
                            .withSize(OutputSize.width(400))
                            .withSun(Sun.at(ZonedDateTime.parse("2024-06-21T06:30-07:00[America/Los_Angeles]")))
                            .withScene(Scene.defaults().withShadows(ShadowAlgorithm.SWEEP))
                            .run(JobListener.NONE);
                    relief.write(Path.of(args[0]),
                            WriteOptions.defaults().withSidecars(WriteOptions.Sidecars.ALWAYS));
                    System.out.println("rendered " + relief.width() + "x" + relief.height() + " in module "
                            + ReliefJob.class.getModule().getName());
                }
            }
            """;

    /** The DEM the CLI draws without FILE (its bundled sample is a copy of it). */
    private static final Path SAMPLE =
            Path.of("testdata/variants/bigtujunga_crop600x400_v04_int16_deflate_pred2_tile256.tif");

    @Test
    void aModuleThatRequiresTheLibraryRendersAndWrites(@TempDir Path dir) throws Exception {
        List<String> modulePath = TestJvm.libraryModulePath(ReliefJob.class);
        assertTrue(Files.exists(Path.of(modulePath.get(0), "module-info.class")), modulePath.get(0));
        Path src = dir.resolve("src/demo");
        Files.createDirectories(src.resolve("demo"));
        Files.writeString(src.resolve("module-info.java"), MODULE_INFO);
        Files.writeString(src.resolve("demo/Main.java"), MAIN);
        Path classes = dir.resolve("mods/demo");

        ByteArrayOutputStream messages = new ByteArrayOutputStream();
        PrintStream out = new PrintStream(messages, true, StandardCharsets.UTF_8);
        int compiled = ToolProvider.findFirst("javac").orElseThrow().run(out, out, "-d", classes.toString(),
                "--module-path", String.join(File.pathSeparator, modulePath),
                src.resolve("module-info.java").toString(), src.resolve("demo/Main.java").toString());
        assertEquals(0, compiled, messages.toString(StandardCharsets.UTF_8));

        Path png = dir.resolve("relief.png");
        List<String> command = new ArrayList<>(List.of(TestJvm.java(), "-Djava.awt.headless=true",
                "--module-path", dir.resolve("mods") + File.pathSeparator + String.join(File.pathSeparator, modulePath),
                "-m", "demo/demo.Main", png.toString(), SAMPLE.toString()));
        ProcessBuilder builder = new ProcessBuilder(command).redirectErrorStream(true);
        builder.environment().remove("SIS_DATA");
        Process p = builder.start();
        String output = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).strip();
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "finished");
        assertEquals(0, p.exitValue(), output);
        // and nothing else: no Apache SIS warning on stderr (SIS_DATA)
        assertEquals("rendered 400x278 in module io.github.jdem846", output);
        assertTrue(Files.exists(dir.resolve("relief.pgw")) && Files.exists(dir.resolve("relief.prj")), "sidecars");

        ReliefResult here = ReliefJob.of(SAMPLE)
                .withWindow(Window.world(380000, 3790000, 400000, 3800000))
                .withSize(OutputSize.width(400))
                .withSun(Sun.at(ZonedDateTime.parse("2024-06-21T06:30-07:00[America/Los_Angeles]")))
                .withScene(Scene.defaults().withShadows(ShadowAlgorithm.SWEEP))
                .run(JobListener.NONE);
        BufferedImage written = ImageIO.read(png.toFile());
        assertArrayEquals(here.argb(), written.getRGB(0, 0, here.width(), here.height(), null, 0, here.width()));
    }
}
