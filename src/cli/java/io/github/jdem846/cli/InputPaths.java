package io.github.jdem846.cli;

import io.github.jdem846.io.DemFormatException;
import io.github.jdem846.io.DemInput;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.nio.file.PathMatcher;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.stream.Stream;
import picocli.CommandLine.Model.CommandSpec;

/**
 * The DEM files the positional arguments of a command name: a file as itself; a directory as the DEM files in it
 * (by extension, sorted by name; other files skipped); a glob pattern that the shell did not expand (quoted, e.g.
 * {@code "tiles/*.hgt"}) as the DEM files it matches, sorted. One file in all is read as itself, several as one
 * grid (a mosaic). A path that names nothing and has no glob characters is kept as it is, so that the reader
 * reports it ("no such file").
 */
final class InputPaths {

    /** Extensions of the DEM files a directory or a glob contributes (a {@code .hdr} stands for its data file). */
    static final Set<String> DEM_EXTENSIONS = Set.of("tif", "tiff", "gtif", "flt", "bil", "hgt", "asc");

    /**
     * The files named, and what a person should know about how they were found.
     *
     * @param input the DEM files, or {@code null} when none was named (the bundled sample)
     * @param notes e.g. "tiles: 4 DEM files (2 other files skipped)"
     */
    record Resolved(DemInput input, List<String> notes) {
    }

    private InputPaths() {
    }

    /**
     * Resolves the arguments.
     *
     * @param spec the command, for usage errors
     * @param args the positional arguments, possibly empty or null
     * @return the files and notes
     * @throws picocli.CommandLine.ParameterException when a glob pattern matches no DEM file (bad usage)
     * @throws DemFormatException                     when a directory holds no DEM file
     */
    static Resolved resolve(CommandSpec spec, List<String> args) throws IOException {
        if (args == null || args.isEmpty()) {
            return new Resolved(null, List.of());
        }
        List<Path> files = new ArrayList<>();
        List<String> notes = new ArrayList<>();
        for (String arg : args) {
            Path p = pathOrNull(arg);
            if (p != null && Files.isDirectory(p)) {
                files.addAll(directory(p, notes));
            } else if ((p == null || !Files.exists(p)) && isGlob(arg)) {
                files.addAll(glob(spec, arg, notes));
            } else {
                files.add(p != null ? p : Path.of(arg)); // an invalid path: Path.of says why
            }
        }
        return new Resolved(DemInput.of(files), notes);
    }

    private static List<Path> directory(Path dir, List<String> notes) throws IOException {
        List<Path> dems = new ArrayList<>();
        int skipped = 0;
        try (Stream<Path> entries = Files.list(dir)) {
            for (Path p : entries.sorted().toList()) {
                if (Files.isRegularFile(p) && DEM_EXTENSIONS.contains(extension(p))) {
                    dems.add(p);
                } else {
                    skipped++;
                }
            }
        }
        if (dems.isEmpty()) {
            throw new DemFormatException(dir, "is a directory with no DEM file in it (looked for ."
                    + String.join(", .", sorted(DEM_EXTENSIONS)) + ")");
        }
        notes.add(dir + ": " + count(dems.size(), "DEM file") + (skipped > 0 ? " (" + count(skipped,
                "other entry") + " skipped)" : ""));
        return dems;
    }

    /**
     * The DEM files a glob pattern matches: the folder before its first glob character is searched, as deep as
     * the pattern has folders (any depth for {@code **}).
     */
    private static List<Path> glob(CommandSpec spec, String pattern, List<String> notes) throws IOException {
        String normal = pattern.replace('\\', '/');
        int firstGlob = firstGlobChar(normal);
        int cut = normal.lastIndexOf('/', firstGlob);
        Path base = cut < 0 ? Path.of("") : Path.of(cut == 0 ? "/" : normal.substring(0, cut));
        String rest = normal.substring(cut + 1);
        int depth = rest.contains("**") ? Integer.MAX_VALUE : rest.split("/").length;
        PathMatcher matcher;
        try {
            matcher = FileSystems.getDefault().getPathMatcher("glob:" + rest);
        } catch (IllegalArgumentException e) {
            throw Usage.error(spec, "'" + pattern + "' is not a valid glob pattern: " + e.getMessage());
        }
        String explicitExt = extension(Path.of(rest.replace('*', 'x').replace('?', 'x').replace('[', 'x')
                .replace(']', 'x').replace('{', 'x').replace('}', 'x')));
        List<Path> dems = new ArrayList<>();
        Path root = base.toString().isEmpty() ? Path.of(".") : base;
        if (Files.isDirectory(root)) {
            try (Stream<Path> walk = Files.walk(root, depth)) {
                for (Path p : walk.sorted().toList()) {
                    Path rel = root.relativize(p);
                    if (Files.isRegularFile(p) && matcher.matches(rel)) {
                        String ext = extension(p);
                        if (DEM_EXTENSIONS.contains(ext) || (!ext.isEmpty() && ext.equals(explicitExt))) {
                            dems.add(base.toString().isEmpty() ? rel : p);
                        }
                    }
                }
            } catch (UncheckedIOException e) {
                throw e.getCause();
            }
        }
        if (dems.isEmpty()) {
            throw Usage.error(spec, "no DEM file matches '" + pattern + "'" + (Files.isDirectory(root) ? ""
                    : " (" + root + " is not a directory)"));
        }
        notes.add(pattern + ": " + count(dems.size(), "DEM file"));
        return dems;
    }

    private static boolean isGlob(String arg) {
        return firstGlobChar(arg) >= 0;
    }

    private static int firstGlobChar(String s) {
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            if (c == '*' || c == '?' || c == '[' || c == '{') {
                return i;
            }
        }
        return -1;
    }

    private static Path pathOrNull(String arg) {
        try {
            return Path.of(arg);
        } catch (InvalidPathException e) {
            return null;
        }
    }

    static String extension(Path p) {
        Path name = p.getFileName();
        if (name == null) {
            return "";
        }
        String s = name.toString();
        int dot = s.lastIndexOf('.');
        return dot < 0 ? "" : s.substring(dot + 1).toLowerCase(Locale.ROOT);
    }

    private static List<String> sorted(Set<String> s) {
        return s.stream().sorted().toList();
    }

    private static String count(int n, String what) {
        return n + " " + what + (n == 1 ? "" : "s");
    }
}
