package io.github.jdem846.io;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import io.github.jdem846.io.esri.SidecarCrs;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Every input of the fuzz corpus ({@code src/test/resources/fuzz-corpus}, found by a seeded mutation fuzzer)
 * either reads or is refused with the readers' own {@link DemFormatException}, whose message names the file or
 * one of its sidecars: through {@link DemReader#read}, {@link DemReader#inspect} and {@link DemReader#statistics}
 * alike, never another exception and never a hang (the timeout).
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class FuzzReproducerTest {

    static final Path CORPUS = Path.of("src/test/resources/fuzz-corpus");

    /** Files read through their data file rather than given themselves. */
    private static final Set<String> SIDECARS = Set.of("hdr", "prj", "txt", "md");

    @FunctionalInterface
    private interface Read {
        Object apply(Path file) throws IOException;
    }

    /** The inputs of the corpus: every file but the READMEs and sidecars, in path order. */
    static Stream<Path> inputs() throws IOException {
        try (Stream<Path> files = Files.walk(CORPUS)) {
            List<Path> inputs = files.filter(Files::isRegularFile)
                    .filter(p -> !SIDECARS.contains(SidecarCrs.extension(p)))
                    .sorted()
                    .toList();
            return inputs.stream();
        }
    }

    @Test
    void theCorpusHoldsTheReproducers() throws IOException {
        List<Path> inputs = inputs().toList();
        assertTrue(inputs.size() >= 8, "the corpus has " + inputs.size() + " inputs: " + inputs);
        for (String format : new String[] {".tif", ".asc", ".flt"}) {
            assertTrue(inputs.stream().anyMatch(p -> p.toString().endsWith(format)), "no " + format + " input");
        }
    }

    @ParameterizedTest
    @MethodSource("inputs")
    void readsOrIsRefusedWithTheFilesName(Path input) {
        String base = input.getFileName().toString().replaceFirst("\\.[^.]*$", "");
        Path named = input.resolveSibling(base);
        for (Read read : new Read[] {DemReader::read, DemReader::inspect, DemReader::statistics}) {
            try {
                read.apply(input);
            } catch (DemFormatException e) {
                String m = e.getMessage();
                // the input itself or a sidecar of it (a .hdr at fault)
                assertTrue(m.startsWith(named + "."), "the message names " + named + ".*: " + m);
                String problem = m.substring(m.indexOf(": ") + 2);
                assertTrue(problem.length() > 8, "a problem is stated: " + m);
                assertTrue(!problem.toLowerCase(Locale.ROOT).contains("exception"), "no exception class: " + m);
            } catch (IOException | RuntimeException | Error e) {
                fail(input + ": " + e, e);
            }
        }
    }
}
