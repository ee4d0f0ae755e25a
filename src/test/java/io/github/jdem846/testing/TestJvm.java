package io.github.jdem846.testing;

import java.io.File;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/** What a test needs to start another JVM on this build's classes and dependencies. */
public final class TestJvm {

    private TestJvm() {
    }

    /** The {@code java} launcher of the running JDK. */
    public static String java() {
        return Path.of(System.getProperty("java.home"), "bin", "java").toString();
    }

    /**
     * This JVM's module path and class path as one class path: the tests run on the module path (the main classes
     * as the patched module {@code io.github.jdem846}), while the CLI, like {@code jdem846-cli.jar}, runs on the
     * class path.
     */
    public static String classPath() {
        return String.join(File.pathSeparator, entries());
    }

    /** The entries of this JVM's module path, then of its class path. */
    public static List<String> entries() {
        List<String> out = new ArrayList<>();
        for (String property : new String[] {"jdk.module.path", "java.class.path"}) {
            for (String e : System.getProperty(property, "").split(File.pathSeparator)) {
                if (!e.isBlank() && !out.contains(e)) {
                    out.add(e);
                }
            }
        }
        return out;
    }

    /** Jars of the tests and of the command line, which a library user does not have. */
    private static final List<String> NOT_OF_THE_LIBRARY = List.of("test-classes", "surefire", "failsafe", "junit",
            "opentest4j", "apiguardian", "picocli", "progressbar", "jline");

    /**
     * What a library user puts on {@code --module-path}: the library's classes (the directory or jar that holds
     * {@code module-info.class}, as this JVM loads the library from) and its runtime dependencies, no test or
     * CLI-only jar.
     *
     * @param library a class of the library
     * @return the entries
     */
    public static List<String> libraryModulePath(Class<?> library) {
        String main;
        try {
            main = Path.of(library.getProtectionDomain().getCodeSource().getLocation().toURI()).toString();
        } catch (URISyntaxException e) {
            throw new IllegalStateException(e);
        }
        if (Files.isDirectory(Path.of(main)) && !Files.exists(Path.of(main, "module-info.class"))) {
            throw new IllegalStateException(main + " does not hold the module descriptor");
        }
        List<String> path = new ArrayList<>(List.of(main));
        for (String e : entries()) {
            if (!e.equals(main) && e.endsWith(".jar") && NOT_OF_THE_LIBRARY.stream().noneMatch(e::contains)) {
                path.add(e);
            }
        }
        return path;
    }
}
