package io.github.jdem846.testing;

import java.io.File;
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
}
