package io.github.jdem846.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;

import io.github.jdem846.job.JobListener;
import io.github.jdem846.job.ReliefJob;
import io.github.jdem846.output.WriteOptions;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import picocli.CommandLine;

/**
 * One default for sidecar files: {@code WriteOptions.defaults()} writes the same files as the CLI without
 * {@code --world-file} (the picture alone), and {@code Sidecars.ALWAYS} the same as {@code --world-file}.
 */
class SidecarDefaultTest {

    private static final Path DEM = Path.of("testdata/dem/luxembourg_srtm30s_wgs84.flt");

    @ParameterizedTest
    @ValueSource(strings = {"png", "tif"})
    void libraryDefaultsWriteWhatTheCliWritesWithoutSidecarOptions(String extension, @TempDir Path dir)
            throws Exception {
        Path cli = cliOutput(dir.resolve("cli"), extension);
        Path library = libraryOutput(dir.resolve("library"), extension, WriteOptions.defaults());
        assertEquals(List.of("out." + extension), files(cli));
        assertEquals(files(cli), files(library));
    }

    @ParameterizedTest
    @ValueSource(strings = {"png", "tif"})
    void sidecarsAlwaysWritesWhatTheCliWritesWithWorldFile(String extension, @TempDir Path dir) throws Exception {
        Path cli = cliOutput(dir.resolve("cli"), extension, "--world-file");
        Path library = libraryOutput(dir.resolve("library"), extension,
                WriteOptions.defaults().withSidecars(WriteOptions.Sidecars.ALWAYS));
        assertEquals(4, files(cli).size(), files(cli).toString());
        assertEquals(files(cli), files(library));
    }

    private static Path cliOutput(Path dir, String extension, String... more) throws IOException {
        Files.createDirectories(dir);
        StringWriter err = new StringWriter();
        CommandLine cl = Main.commandLine();
        cl.setErr(new PrintWriter(err));
        String[] args = Stream.concat(Stream.of("render", "-q", DEM.toString(), "-o",
                dir.resolve("out." + extension).toString()), Stream.of(more)).toArray(String[]::new);
        assertEquals(0, cl.execute(args), err.toString());
        return dir;
    }

    private static Path libraryOutput(Path dir, String extension, WriteOptions options) throws Exception {
        Files.createDirectories(dir);
        ReliefJob.of(DEM).run(JobListener.NONE).write(dir.resolve("out." + extension), options);
        return dir;
    }

    private static List<String> files(Path dir) throws IOException {
        try (Stream<Path> files = Files.list(dir)) {
            return files.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }
}
