package io.github.jdem846.cli;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.CountDownLatch;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

class WarmUpThreadTest {

    private final CountDownLatch release = new CountDownLatch(1);

    @AfterEach
    void restore() {
        System.clearProperty(WarmUpThread.PROPERTY);
        release.countDown();
    }

    @Test
    void startsADaemonThreadOnlyWhenTheWarmUpsAreOn() {
        assertFalse(WarmUpThread.enabled(), "off by default");
        WarmUpThread.start("warm-up-test-default", this::waitForRelease);
        assertFalse(alive("warm-up-test-default"), "no thread by default");

        System.setProperty(WarmUpThread.PROPERTY, "on");
        assertTrue(WarmUpThread.enabled());
        WarmUpThread.start("warm-up-test-on", this::waitForRelease);
        assertTrue(alive("warm-up-test-on"), "-Djdem846.warmUp=on: a warm-up thread while its work waits");

        System.setProperty(WarmUpThread.PROPERTY, "off");
        assertFalse(WarmUpThread.enabled(), "any other value leaves them off");
    }

    private void waitForRelease() {
        try {
            release.await();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private static boolean alive(String name) {
        return Thread.getAllStackTraces().keySet().stream()
                .anyMatch(t -> t.getName().equals(name) && t.isAlive() && t.isDaemon());
    }
}
