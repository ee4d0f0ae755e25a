package io.github.jdem846.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.stream.Stream;
import picocli.CommandLine;

/**
 * The training run of the launcher's ahead-of-time cache (JDK 25 and later, {@code bin/jdem846}): every command on
 * the bundled sample, in one JVM started with {@code -XX:AOTMode=record}, so that the cache made from it holds the
 * classes each command loads, already linked, and how their methods ran (docs/performance.md, "Start-up and
 * class-data sharing"). Not a user command: the launcher runs it in the background once per JDK and jar.
 */
public final class AotTraining {

    /**
     * The commands run; {@code %sample} stands for the sample's file, {@code @name} for the file or folder
     * {@code name} in the work directory.
     */
    private static final List<List<String>> COMMANDS = List.of(
            List.of("hillshade", "-q", "-o", "@hillshade.png", "%sample"),
            List.of("hillshade", "-q", "--method", "horn", "-o", "@horn.tif", "%sample"),
            List.of("render", "-q", "-o", "@render.png", "%sample"),
            List.of("render", "-q", "--shadows", "sweep", "--ambient", "0.5", "-o", "@render.jpg", "%sample"),
            List.of("tint", "-q", "-o", "@tint.png", "%sample"),
            List.of("shadows", "-q", "-o", "@shadows.png", "%sample"),
            List.of("skyview", "-q", "--sky-directions", "8", "-o", "@skyview.png", "%sample"),
            List.of("view", "-q", "--width", "320", "-o", "@view.png", "%sample"),
            List.of("tiles", "-q", "-Z", "9-10", "-o", "@tiles", "%sample"),
            List.of("info", "--json", "%sample"),
            List.of("sun", "--at", "34.3,-118.2", "--time", "2024-06-21T12:00:00Z"));

    private AotTraining() {
    }

    /**
     * Runs {@link #train}; exit status 1 when a command failed.
     *
     * @param args none
     * @throws IOException when the work directory or the sample cannot be written
     */
    public static void main(String[] args) throws IOException {
        System.exit(train().isEmpty() ? 0 : 1);
    }

    /**
     * Runs the commands in a new temporary directory, which it deletes after.
     *
     * @return the commands that failed
     * @throws IOException when the directory or the sample cannot be written
     */
    static List<List<String>> train() throws IOException {
        Path dir = Files.createTempDirectory("jdem846-training-");
        List<List<String>> failed = new ArrayList<>();
        try {
            String sample = BundledSample.extract().first().toString();
            for (List<String> command : COMMANDS) {
                if (run(command, sample, dir) != 0) {
                    failed.add(command);
                }
            }
        } finally {
            deleteTree(dir);
        }
        return failed;
    }

    private static int run(List<String> command, String sample, Path dir) {
        String[] args = command.stream()
                .map(a -> a.equals("%sample") ? sample
                        : a.startsWith("@") ? dir.resolve(a.substring(1)).toString() : a)
                .toArray(String[]::new);
        CommandLine cl = Main.commandLine(args);
        StringWriter sink = new StringWriter();
        cl.setOut(new PrintWriter(sink));
        cl.setErr(new PrintWriter(sink));
        return Main.execute(cl, args);
    }

    private static void deleteTree(Path dir) throws IOException {
        try (Stream<Path> files = Files.walk(dir)) {
            for (Path p : files.sorted(Comparator.reverseOrder()).toList()) {
                Files.deleteIfExists(p);
            }
        }
    }
}
