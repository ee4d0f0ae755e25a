package io.github.jdem846;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.job.JobListener;
import io.github.jdem846.job.ReliefJob;
import io.github.jdem846.job.ReliefResult;
import io.github.jdem846.testing.TestJvm;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.lang.module.ModuleDescriptor;
import java.lang.module.ModuleFinder;
import java.lang.module.ModuleReference;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Collections;
import java.util.List;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;
import java.util.zip.ZipEntry;
import java.util.zip.ZipFile;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * What {@code mvn package} built (run by failsafe after it): the library jar holds the library only, the cli
 * classifier jar the command line and the sample only, and {@code jdem846-cli.jar} runs on its own.
 */
class PackagingIT {

    private static final Path LIBRARY = Path.of(System.getProperty("jdem846.libraryJar"));
    private static final Path CLI = Path.of(System.getProperty("jdem846.cliJar"));
    /** The cli classifier jar: {@code jdem846-<version>-cli.jar} beside the library jar. */
    private static final Path CLI_CLASSES = LIBRARY.resolveSibling(
            LIBRARY.getFileName().toString().replaceFirst("\\.jar$", "-cli.jar"));
    /** The file the CLI's bundled sample is a copy of. */
    private static final Path SAMPLE =
            Path.of("testdata/variants/bigtujunga_crop600x400_v04_int16_deflate_pred2_tile256.tif");

    @Test
    void theLibraryJarHoldsNeitherTheCommandLineNorTheSample() throws IOException {
        List<String> names = entries(LIBRARY);
        assertTrue(names.contains("io/github/jdem846/job/ReliefJob.class"), "the library is there");
        assertEquals(List.of(), names.stream().filter(n -> n.startsWith("io/github/jdem846/cli/")
                || n.startsWith("io/github/jdem846/sample/") || n.endsWith(".tif") || n.startsWith("picocli/"))
                .toList());
    }

    @Test
    void theModuleDescriptorNamesNothingOfTheCommandLine() {
        Set<ModuleReference> modules = ModuleFinder.of(LIBRARY).findAll();
        assertEquals(1, modules.size());
        ModuleDescriptor d = modules.iterator().next().descriptor();
        assertEquals("io.github.jdem846", d.name());
        assertFalse(d.packages().contains("io.github.jdem846.cli"), d.packages().toString());
        Set<String> required = d.requires().stream().map(ModuleDescriptor.Requires::name).collect(Collectors.toSet());
        assertTrue(Collections.disjoint(required, Set.of("info.picocli", "me.tongfei.progressbar",
                "java.management")), required.toString());
        assertTrue(d.opens().isEmpty(), d.opens().toString());
    }

    @Test
    void theCliClassifierJarHoldsTheCommandLineAndTheSampleOnly() throws IOException {
        List<String> names = entries(CLI_CLASSES);
        assertTrue(names.contains("io/github/jdem846/cli/Main.class"), names.toString());
        assertTrue(names.contains("io/github/jdem846/cli/TilesCommand.class"), "for the Spark module");
        assertTrue(names.stream().anyMatch(n -> n.startsWith("io/github/jdem846/sample/") && n.endsWith(".tif")));
        assertEquals(List.of(), names.stream().filter(n -> n.endsWith(".class")
                && !n.startsWith("io/github/jdem846/cli/")).toList());
        assertArrayEquals(Files.readAllBytes(SAMPLE), sampleIn(CLI_CLASSES), "the sample is the test file's copy");
    }

    @Test
    void theCliJarPrintsItsVersion() throws Exception {
        Run run = run("--version");
        assertEquals(0, run.status(), run.err());
        String version = Files.readString(Path.of("pom.xml")).replaceFirst("(?s).*?</artifactId>\\s*<version>([^<]+)"
                + "</version>.*", "$1");
        assertEquals("jdem846 " + version, run.out().lines().findFirst().orElse(""), run.out());
    }

    @Test
    void theCliJarRendersTheSampleAsTheLibraryRendersItsFile(@TempDir Path dir) throws Exception {
        Path png = dir.resolve("sample.png");
        Run run = run("render", "-o", png.toString());
        assertEquals(0, run.status(), run.err());
        assertTrue(run.err().contains("bundled sample"), run.err());

        ReliefResult here = ReliefJob.of(SAMPLE).run(JobListener.NONE);
        BufferedImage written = ImageIO.read(png.toFile());
        assertEquals(600, written.getWidth());
        assertEquals(400, written.getHeight());
        assertArrayEquals(here.argb(), written.getRGB(0, 0, here.width(), here.height(), null, 0, here.width()));
    }

    private record Run(int status, String out, String err) {
    }

    private static Run run(String... args) throws Exception {
        List<String> command = new java.util.ArrayList<>(List.of(TestJvm.java(), "-Djava.awt.headless=true",
                "-jar", CLI.toString()));
        command.addAll(List.of(args));
        Path err = Files.createTempFile("jdem846-it-", ".err");
        try {
            Process p = new ProcessBuilder(command).redirectError(err.toFile()).start();
            String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            assertTrue(p.waitFor(120, TimeUnit.SECONDS), "finished");
            return new Run(p.exitValue(), out, Files.readString(err));
        } finally {
            Files.deleteIfExists(err);
        }
    }

    private static List<String> entries(Path jar) throws IOException {
        try (ZipFile zip = new ZipFile(jar.toFile())) {
            return zip.stream().map(ZipEntry::getName).toList();
        }
    }

    private static byte[] sampleIn(Path jar) throws IOException {
        try (ZipFile zip = new ZipFile(jar.toFile())) {
            ZipEntry e = zip.getEntry("io/github/jdem846/sample/" + SAMPLE.getFileName());
            try (var in = zip.getInputStream(e)) {
                return in.readAllBytes();
            }
        }
    }
}
